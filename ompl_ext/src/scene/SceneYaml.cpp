#include "ropras/ompl_ext/scene/SceneYaml.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"

namespace ropras::ompl_ext
{
    namespace
    {
        /// quaternions whose norm is within this of 1 are normalized; others are rejected
        constexpr double QUATERNION_NORM_TOLERANCE = 1e-2;

        /// Reads one YAML document and reports every problem as "source:line: where: what".
        class Reader
        {
        public:
            explicit Reader(std::string source) : source_(std::move(source)) {}

            [[noreturn]] void fail(const YAML::Node &node, const std::string &where, const std::string &what) const
            {
                std::ostringstream msg;
                msg << source_;
                if (node.IsDefined() && node.Mark().line >= 0)
                    msg << ':' << node.Mark().line + 1;
                msg << ": " << where << ": " << what;
                throw Error(msg.str());
            }

            YAML::Node parse(const std::string &text) const
            {
                try
                {
                    return YAML::Load(text);
                }
                catch (const YAML::Exception &e)
                {
                    std::ostringstream msg;
                    msg << source_ << ':' << e.mark.line + 1 << ": malformed YAML: " << e.msg;
                    throw Error(msg.str());
                }
            }

            /// node[key], which must exist
            YAML::Node child(const YAML::Node &node, const std::string &key, const std::string &where) const
            {
                if (!node.IsMap())
                    fail(node, where, "expected a mapping with key '" + key + "'");
                YAML::Node value = node[key];
                if (!value.IsDefined() || value.IsNull())
                    fail(node, where, "missing key '" + key + "'");
                return value;
            }

            YAML::Node sequence(const YAML::Node &node, const std::string &where) const
            {
                if (!node.IsSequence())
                    fail(node, where, "expected a list");
                return node;
            }

            double number(const YAML::Node &node, const std::string &where) const
            {
                if (!node.IsScalar())
                    fail(node, where, "expected a number");
                double value = 0.0;
                try
                {
                    value = node.as<double>();
                }
                catch (const YAML::Exception &)
                {
                    fail(node, where, "'" + node.Scalar() + "' is not a number");
                }
                if (!std::isfinite(value))
                    fail(node, where, "value '" + node.Scalar() + "' is not finite");
                return value;
            }

            std::string string(const YAML::Node &node, const std::string &where) const
            {
                if (!node.IsScalar())
                    fail(node, where, "expected a string");
                return node.Scalar();
            }

            /// [x, y, z] or {x: .., y: .., z: ..}
            Eigen::Vector3d vector3(const YAML::Node &node, const std::string &where) const
            {
                Eigen::Vector3d v;
                if (node.IsSequence())
                {
                    if (node.size() != 3)
                        fail(node, where, "expected 3 values, got " + std::to_string(node.size()));
                    for (std::size_t i = 0; i < 3; ++i)
                        v[int(i)] = number(node[i], where + "[" + std::to_string(i) + "]");
                }
                else if (node.IsMap())
                {
                    const char *keys[3] = {"x", "y", "z"};
                    for (int i = 0; i < 3; ++i)
                        v[i] = number(child(node, keys[i], where), where + "." + keys[i]);
                }
                else
                    fail(node, where, "expected [x, y, z] or {x, y, z}");
                return v;
            }

            /// [x, y, z, w] or {x, y, z, w}; near-unit quaternions are normalized, others rejected
            Eigen::Quaterniond quaternion(const YAML::Node &node, const std::string &where) const
            {
                double c[4];
                if (node.IsSequence())
                {
                    if (node.size() != 4)
                        fail(node, where,
                             "expected a quaternion [x, y, z, w] (4 values), got " + std::to_string(node.size()) +
                                 " values");
                    for (std::size_t i = 0; i < 4; ++i)
                        c[i] = number(node[i], where + "[" + std::to_string(i) + "]");
                }
                else if (node.IsMap())
                {
                    const char *keys[4] = {"x", "y", "z", "w"};
                    for (int i = 0; i < 4; ++i)
                        c[i] = number(child(node, keys[i], where), where + "." + keys[i]);
                }
                else
                    fail(node, where, "expected a quaternion [x, y, z, w] or {x, y, z, w}");
                Eigen::Quaterniond q(c[3], c[0], c[1], c[2]);
                const double norm = q.norm();
                if (std::abs(norm - 1.0) > QUATERNION_NORM_TOLERANCE)
                {
                    std::ostringstream what;
                    what << "quaternion [" << c[0] << ", " << c[1] << ", " << c[2] << ", " << c[3] << "] has norm "
                         << norm << (norm == 0.0 ? " (zero quaternion)" : "") << "; expected a unit quaternion";
                    fail(node, where, what.str());
                }
                q.coeffs() /= norm;
                return q;
            }

            Eigen::Isometry3d pose(const YAML::Node &node, const std::string &where) const
            {
                if (!node.IsMap())
                    fail(node, where, "expected a pose {position, orientation}");
                Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
                pose.translation() = vector3(child(node, "position", where), where + ".position");
                pose.linear() =
                    quaternion(child(node, "orientation", where), where + ".orientation").toRotationMatrix();
                return pose;
            }

            const std::string &source() const { return source_; }

        private:
            std::string source_;
        };

        std::string lower(std::string s)
        {
            std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
            return s;
        }

        bool nonEmpty(const YAML::Node &node)
        {
            return node.IsDefined() && !node.IsNull() && !(node.IsSequence() && node.size() == 0);
        }

        /// one primitive (shape_msgs/SolidPrimitive) with its pose in the object frame
        Shape readPrimitive(const Reader &reader, const YAML::Node &node, const Eigen::Isometry3d &pose,
                            const std::string &where)
        {
            const YAML::Node typeNode = reader.child(node, "type", where);
            const std::string typeText = lower(reader.string(typeNode, where + ".type"));
            // SolidPrimitive constants: BOX = 1, SPHERE = 2, CYLINDER = 3, CONE = 4
            std::string type;
            if (typeText == "box" || typeText == "1")
                type = "box";
            else if (typeText == "sphere" || typeText == "2")
                type = "sphere";
            else if (typeText == "cylinder" || typeText == "3")
                type = "cylinder";
            else
                reader.fail(
                    typeNode, where + ".type",
                    "unsupported primitive type '" + typeNode.Scalar() + "' (expected box, sphere or cylinder)");

            const YAML::Node dims = reader.sequence(reader.child(node, "dimensions", where), where + ".dimensions");
            const std::size_t expected = type == "box" ? 3 : type == "sphere" ? 1 : 2;
            if (dims.size() != expected)
            {
                const char *meaning = type == "box" ? "[x, y, z]" : type == "sphere" ? "[radius]" : "[length, radius]";
                reader.fail(dims, where + ".dimensions",
                            type + " needs " + std::to_string(expected) + " dimensions " + meaning + ", got " +
                                std::to_string(dims.size()));
            }
            double d[3] = {0.0, 0.0, 0.0};
            for (std::size_t i = 0; i < expected; ++i)
            {
                d[i] = reader.number(dims[i], where + ".dimensions[" + std::to_string(i) + "]");
                if (d[i] <= 0.0)
                {
                    std::ostringstream what;
                    what << type << " dimension " << d[i] << " must be positive";
                    reader.fail(dims[i], where + ".dimensions[" + std::to_string(i) + "]", what.str());
                }
            }
            if (type == "box")
                return Shape::box(Eigen::Vector3d(d[0], d[1], d[2]), pose);
            if (type == "sphere")
                return Shape::sphere(d[0], pose);
            return Shape::cylinder(d[1], d[0], pose);
        }

        void readCollisionObject(const Reader &reader, const YAML::Node &node, const std::string &where,
                                 std::set<std::string> &ids, Environment &env)
        {
            if (!node.IsMap())
                reader.fail(node, where,
                            "expected a collision object (a mapping with id, primitives, primitive_poses)");
            const YAML::Node idNode = reader.child(node, "id", where);
            const std::string id = reader.string(idNode, where + ".id");
            if (id.empty())
                reader.fail(idNode, where + ".id", "empty object id");
            const std::string at = where + " '" + id + "'";
            if (!ids.insert(id).second)
                reader.fail(idNode, at, "duplicate object id '" + id + "'");

            if (const YAML::Node op = node["operation"]; op.IsDefined() && !op.IsNull())
            {
                const std::string text = lower(reader.string(op, at + ".operation"));
                // CollisionObject constants: ADD = 0, REMOVE = 1, APPEND = 2, MOVE = 3
                if (text != "0" && text != "add")
                    reader.fail(op, at + ".operation",
                                "only ADD (0) is supported in a scene, got '" + op.Scalar() + "'");
            }
            for (const char *unsupported : {"meshes", "planes"})
            {
                if (nonEmpty(node[unsupported]))
                    reader.fail(
                        node[unsupported], at + "." + unsupported,
                        std::string(unsupported) + " are not supported (box, sphere and cylinder primitives only)");
            }

            Eigen::Isometry3d objectPose = Eigen::Isometry3d::Identity();
            if (const YAML::Node p = node["pose"]; p.IsDefined() && !p.IsNull())
                objectPose = reader.pose(p, at + ".pose");

            const YAML::Node primitives = reader.sequence(reader.child(node, "primitives", at), at + ".primitives");
            const YAML::Node poses =
                reader.sequence(reader.child(node, "primitive_poses", at), at + ".primitive_poses");
            if (primitives.size() == 0)
                reader.fail(primitives, at + ".primitives", "object has no primitives");
            if (primitives.size() != poses.size())
                reader.fail(poses, at + ".primitive_poses",
                            std::to_string(primitives.size()) + " primitives but " + std::to_string(poses.size()) +
                                " primitive_poses");
            std::vector<Shape> shapes;
            shapes.reserve(primitives.size());
            for (std::size_t k = 0; k < primitives.size(); ++k)
            {
                const std::string index = "[" + std::to_string(k) + "]";
                const Eigen::Isometry3d pose = reader.pose(poses[k], at + ".primitive_poses" + index);
                shapes.push_back(readPrimitive(reader, primitives[k], pose, at + ".primitives" + index));
            }
            try
            {
                env.addObject(id, std::move(shapes), objectPose);
            }
            catch (const Error &e)
            {
                reader.fail(node, at, e.what());
            }
        }

        Environment readScene(const Reader &reader, const YAML::Node &root)
        {
            if (!root.IsMap())
                reader.fail(root, "document", "expected a MoveIt PlanningScene (a mapping with 'world')");
            const YAML::Node world = root["world"];
            if (!world.IsDefined())
                reader.fail(root, "document", "no 'world' key: not a MoveIt PlanningScene");
            Environment env;
            if (world.IsNull())
                return env;
            if (!world.IsMap())
                reader.fail(world, "world", "expected a mapping with 'collision_objects'");
            const YAML::Node objects = world["collision_objects"];
            if (!objects.IsDefined() || objects.IsNull())
                return env;
            reader.sequence(objects, "world.collision_objects");
            std::set<std::string> ids;
            for (std::size_t i = 0; i < objects.size(); ++i)
                readCollisionObject(reader, objects[i], "world.collision_objects[" + std::to_string(i) + "]", ids, env);
            return env;
        }

        MotionPlanRequest readRequest(const Reader &reader, const YAML::Node &root)
        {
            if (!root.IsMap())
                reader.fail(root, "document", "expected a MoveIt MotionPlanRequest (a mapping)");
            MotionPlanRequest request;

            const YAML::Node startState = reader.child(root, "start_state", "document");
            const YAML::Node jointState = reader.child(startState, "joint_state", "start_state");
            const YAML::Node names = reader.sequence(reader.child(jointState, "name", "start_state.joint_state"),
                                                     "start_state.joint_state.name");
            const YAML::Node positions = reader.sequence(
                reader.child(jointState, "position", "start_state.joint_state"), "start_state.joint_state.position");
            if (names.size() != positions.size())
                reader.fail(positions, "start_state.joint_state",
                            std::to_string(names.size()) + " joint names but " + std::to_string(positions.size()) +
                                " positions");
            for (std::size_t i = 0; i < names.size(); ++i)
            {
                const std::string where = "start_state.joint_state.name[" + std::to_string(i) + "]";
                const std::string name = reader.string(names[i], where);
                const double value = reader.number(
                    positions[i], "start_state.joint_state.position[" + std::to_string(i) + "] (" + name + ")");
                if (!request.start.emplace(name, value).second)
                    reader.fail(names[i], where, "duplicate joint name '" + name + "'");
            }

            const YAML::Node goals =
                reader.sequence(reader.child(root, "goal_constraints", "document"), "goal_constraints");
            if (goals.size() == 0)
                reader.fail(goals, "goal_constraints", "no goal constraints");
            const YAML::Node joints =
                reader.sequence(reader.child(goals[0], "joint_constraints", "goal_constraints[0]"),
                                "goal_constraints[0].joint_constraints");
            if (joints.size() == 0)
                reader.fail(joints, "goal_constraints[0].joint_constraints", "no joint constraints");
            for (std::size_t i = 0; i < joints.size(); ++i)
            {
                const std::string where = "goal_constraints[0].joint_constraints[" + std::to_string(i) + "]";
                const std::string name =
                    reader.string(reader.child(joints[i], "joint_name", where), where + ".joint_name");
                const double value =
                    reader.number(reader.child(joints[i], "position", where), where + ".position (" + name + ")");
                if (!request.goal.emplace(name, value).second)
                    reader.fail(joints[i], where, "duplicate joint name '" + name + "'");
            }
            return request;
        }
    }  // namespace

    Environment planningSceneFromString(const std::string &yaml, const std::string &sourceName)
    {
        const Reader reader(sourceName);
        return readScene(reader, reader.parse(yaml));
    }

    Environment loadPlanningScene(const std::string &path)
    {
        return planningSceneFromString(readInputFile(path, "scene"), path);
    }

    MotionPlanRequest motionPlanRequestFromString(const std::string &yaml, const std::string &sourceName)
    {
        const Reader reader(sourceName);
        return readRequest(reader, reader.parse(yaml));
    }

    MotionPlanRequest loadMotionPlanRequest(const std::string &path)
    {
        return motionPlanRequestFromString(readInputFile(path, "request"), path);
    }
}  // namespace ropras::ompl_ext
