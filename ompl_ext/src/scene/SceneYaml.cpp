#include "ropras/ompl_ext/scene/SceneYaml.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <vector>

#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/ompl_ext/scene/PointCloud.h"
#include "ropras/ompl_ext/scene/PointCloudFile.h"

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

            /** yaml-cpp keeps one of two equal keys of a mapping without a word: a scene whose second `world:` or
                request whose second `position:` silently wins or loses. Every mapping is checked (iteratively: no
                recursion depth to exhaust). */
            void rejectDuplicateKeys(const YAML::Node &root) const
            {
                constexpr std::size_t MAX_NODES = 50000000;  // aliases can make a small file a huge tree
                std::vector<YAML::Node> pending{root};
                for (std::size_t visited = 0; !pending.empty(); ++visited)
                {
                    const YAML::Node node = pending.back();
                    pending.pop_back();
                    if (visited > MAX_NODES)
                        fail(
                            root, "document",
                            "more than " + std::to_string(MAX_NODES) + " YAML nodes (aliases repeating a large node?)");
                    if (node.IsSequence())
                        for (const YAML::Node &item : node)
                            pending.push_back(item);
                    if (!node.IsMap())
                        continue;
                    std::map<std::string, int> lines;
                    for (const auto &entry : node)
                    {
                        const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
                        const auto [it, fresh] = lines.emplace(key, entry.first.Mark().line + 1);
                        if (!fresh && entry.first.IsScalar())
                            fail(entry.first, "key '" + key + "'",
                                 "given twice in one mapping (first on line " + std::to_string(it->second) + ")");
                        pending.push_back(entry.second);
                    }
                }
            }

            YAML::Node parse(const std::string &text) const
            {
                try
                {
                    YAML::Node root = YAML::Load(text);
                    rejectDuplicateKeys(root);
                    return root;
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

        /// the primitives of a CollisionObject with their poses (in the object frame)
        std::vector<Shape> readShapes(const Reader &reader, const YAML::Node &node, const std::string &at)
        {
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
            return shapes;
        }

        /// the object's id (node.id: non-empty, unique in \a ids)
        std::string objectId(const Reader &reader, const YAML::Node &node, const std::string &where,
                             std::set<std::string> &ids)
        {
            const YAML::Node idNode = reader.child(node, "id", where);
            const std::string id = reader.string(idNode, where + ".id");
            if (id.empty())
                reader.fail(idNode, where + ".id", "empty object id");
            const std::string at = where + " '" + id + "'";
            if (!ids.insert(id).second)
                reader.fail(idNode, at, "duplicate object id '" + id + "'");
            return id;
        }

        void readCollisionObject(const Reader &reader, const YAML::Node &node, const std::string &where,
                                 std::set<std::string> &ids, Environment &env)
        {
            if (!node.IsMap())
                reader.fail(node, where,
                            "expected a collision object (a mapping with id, primitives, primitive_poses)");
            const std::string id = objectId(reader, node, where, ids);
            const std::string at = where + " '" + id + "'";

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
            std::vector<Shape> shapes = readShapes(reader, node, at);
            try
            {
                env.addObject(id, std::move(shapes), objectPose);
            }
            catch (const Error &e)
            {
                reader.fail(node, at, e.what());
            }
        }

        /// robot_state.attached_collision_objects[i]: attached to the link, the object's pose in the link frame
        void readAttachedObject(const Reader &reader, const YAML::Node &node, const std::string &where,
                                std::set<std::string> &ids, const std::shared_ptr<const RobotModel> &robot,
                                Environment &env)
        {
            if (!node.IsMap())
                reader.fail(node, where, "expected an attached collision object (a mapping with link_name, object)");
            const std::string link = reader.string(reader.child(node, "link_name", where), where + ".link_name");
            const YAML::Node object = reader.child(node, "object", where);
            if (!object.IsMap())
                reader.fail(object, where + ".object", "expected a collision object (id, primitives, primitive_poses)");
            const YAML::Node idNode = reader.child(object, "id", where + ".object");
            const std::string id = reader.string(idNode, where + ".object.id");
            if (id.empty())
                reader.fail(idNode, where + ".object.id", "empty object id");
            const std::string at = where + " '" + id + "'";
            if (!ids.insert(id).second)
                reader.fail(idNode, at, "duplicate object id '" + id + "'");
            if (!robot)
                reader.fail(node, at,
                            "attached collision objects need the robot model (load the scene with the robot)");
            if (const YAML::Node header = object["header"]; header.IsMap() && header["frame_id"].IsDefined())
            {
                const std::string frame = reader.string(header["frame_id"], at + ".object.header.frame_id");
                if (!frame.empty() && frame != link)
                    reader.fail(header["frame_id"], at + ".object.header.frame_id",
                                "the object's pose must be given in its link's frame '" + link + "', got frame '" +
                                    frame + "'");
            }
            for (const char *unsupported : {"meshes", "planes"})
                if (nonEmpty(object[unsupported]))
                    reader.fail(
                        object[unsupported], at + ".object." + unsupported,
                        std::string(unsupported) + " are not supported (box, sphere and cylinder primitives only)");
            AttachedBody body;
            body.name = id;
            body.link = link;
            if (const YAML::Node p = object["pose"]; p.IsDefined() && !p.IsNull())
                body.pose = reader.pose(p, at + ".object.pose");
            body.shapes = readShapes(reader, object, at + ".object");
            if (const YAML::Node touch = node["touch_links"]; touch.IsDefined() && !touch.IsNull())
            {
                reader.sequence(touch, at + ".touch_links");
                for (std::size_t k = 0; k < touch.size(); ++k)
                    body.touchLinks.push_back(reader.string(touch[k], at + ".touch_links[" + std::to_string(k) + "]"));
            }
            try
            {
                env.attach(robot, std::move(body));
            }
            catch (const Error &e)
            {
                reader.fail(node, at, e.what());
            }
        }

        void readAttachedObjects(const Reader &reader, const YAML::Node &root, std::set<std::string> &ids,
                                 const std::shared_ptr<const RobotModel> &robot, Environment &env)
        {
            const YAML::Node state = root["robot_state"];
            if (!state.IsDefined() || state.IsNull())
                return;
            if (!state.IsMap())
                reader.fail(state, "robot_state", "expected a mapping");
            const YAML::Node attached = state["attached_collision_objects"];
            if (!attached.IsDefined() || attached.IsNull())
                return;
            reader.sequence(attached, "robot_state.attached_collision_objects");
            for (std::size_t i = 0; i < attached.size(); ++i)
                readAttachedObject(reader, attached[i],
                                   "robot_state.attached_collision_objects[" + std::to_string(i) + "]", ids, robot,
                                   env);
        }

        /** world.point_clouds[i] (a ropras extension: MoveIt scenes carry no point cloud files): id, file (PCD or
            PLY, relative to the scene file's folder), point_radius (m, default 0), pose (the sensor's, default
            identity), drop_non_finite (default false) */
        void readPointCloud(const Reader &reader, const YAML::Node &node, const std::string &where,
                            std::set<std::string> &ids, Environment &env)
        {
            if (!node.IsMap())
                reader.fail(node, where, "expected a point cloud (a mapping with id, file, point_radius, pose)");
            const std::string id = objectId(reader, node, where, ids);
            const std::string at = where + " '" + id + "'";
            const YAML::Node fileNode = reader.child(node, "file", at);
            std::filesystem::path file = reader.string(fileNode, at + ".file");
            if (file.is_relative())
                file = std::filesystem::path(reader.source()).parent_path() / file;
            double radius = 0.0;
            if (const YAML::Node r = node["point_radius"]; r.IsDefined() && !r.IsNull())
            {
                radius = reader.number(r, at + ".point_radius");
                if (radius < 0.0 || radius > 1e3)
                    reader.fail(r, at + ".point_radius", "must be in [0, 1000] m, got " + r.Scalar());
            }
            Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
            if (const YAML::Node p = node["pose"]; p.IsDefined() && !p.IsNull())
                pose = reader.pose(p, at + ".pose");
            PointCloudFileOptions options;
            if (const YAML::Node d = node["drop_non_finite"]; d.IsDefined() && !d.IsNull())
            {
                const std::string text = lower(reader.string(d, at + ".drop_non_finite"));
                if (text != "true" && text != "false")
                    reader.fail(d, at + ".drop_non_finite", "expected true or false, got '" + d.Scalar() + "'");
                options.dropNonFinite = text == "true";
            }
            try
            {
                env.addPointCloud(id, PointCloud::build(loadPointCloudFile(file.string(), options), float(radius)),
                                  pose);
            }
            catch (const Error &e)
            {
                reader.fail(fileNode, at + ".file", e.what());
            }
        }

        Environment readScene(const Reader &reader, const YAML::Node &root,
                              const std::shared_ptr<const RobotModel> &robot)
        {
            if (!root.IsMap())
                reader.fail(root, "document", "expected a MoveIt PlanningScene (a mapping with 'world')");
            const YAML::Node world = root["world"];
            if (!world.IsDefined())
                reader.fail(root, "document", "no 'world' key: not a MoveIt PlanningScene");
            Environment env;
            std::set<std::string> ids;
            if (!world.IsNull())
            {
                if (!world.IsMap())
                    reader.fail(world, "world", "expected a mapping with 'collision_objects'");
                const YAML::Node objects = world["collision_objects"];
                if (objects.IsDefined() && !objects.IsNull())
                {
                    reader.sequence(objects, "world.collision_objects");
                    for (std::size_t i = 0; i < objects.size(); ++i)
                        readCollisionObject(reader, objects[i], "world.collision_objects[" + std::to_string(i) + "]",
                                            ids, env);
                }
                if (const YAML::Node clouds = world["point_clouds"]; clouds.IsDefined() && !clouds.IsNull())
                {
                    reader.sequence(clouds, "world.point_clouds");
                    for (std::size_t i = 0; i < clouds.size(); ++i)
                        readPointCloud(reader, clouds[i], "world.point_clouds[" + std::to_string(i) + "]", ids, env);
                }
            }
            readAttachedObjects(reader, root, ids, robot, env);
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
            if (const YAML::Node group = root["group_name"]; group.IsDefined() && !group.IsNull())
                request.group = reader.string(group, "group_name");
            return request;
        }
    }  // namespace

    Environment planningSceneFromString(const std::string &yaml, const std::string &sourceName,
                                        std::shared_ptr<const RobotModel> robot)
    {
        const Reader reader(sourceName);
        return readScene(reader, reader.parse(yaml), robot);
    }

    Environment planningSceneFromString(const std::string &yaml, const std::string &sourceName)
    {
        return planningSceneFromString(yaml, sourceName, nullptr);
    }

    Environment loadPlanningScene(const std::string &path, std::shared_ptr<const RobotModel> robot)
    {
        return planningSceneFromString(readInputFile(path, "scene"), path, std::move(robot));
    }

    Environment loadPlanningScene(const std::string &path)
    {
        return loadPlanningScene(path, nullptr);
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
