#include "ropras/ompl_ext/scene/SceneYaml.h"

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
#include "scene/YamlTree.h"

namespace ropras::ompl_ext
{
    namespace
    {
        /// quaternions whose norm is within this of 1 are normalized; others are rejected
        constexpr double QUATERNION_NORM_TOLERANCE = 1e-2;

        /// Reads the values of one YAML document and reports every problem as "source:line: where: what".
        class Reader
        {
        public:
            explicit Reader(std::string source) : source_(std::move(source)) {}

            [[noreturn]] void fail(const YamlNode &node, const std::string &where, const std::string &what) const
            {
                throwYamlError(source_, node.isDefined() ? node.line() : -1, where, what);
            }

            /// node[key], which must exist
            YamlNode child(const YamlNode &node, const std::string &key, const std::string &where) const
            {
                if (!node.isMap())
                    fail(node, where, "expected a mapping with key '" + key + "'");
                YamlNode value = node[key];
                if (!value.isDefined() || value.isNull())
                    fail(node, where, "missing key '" + key + "'");
                return value;
            }

            YamlNode sequence(const YamlNode &node, const std::string &where) const
            {
                if (!node.isSequence())
                    fail(node, where, "expected a list");
                return node;
            }

            double number(const YamlNode &node, const std::string &where) const
            {
                if (!node.isScalar())
                    fail(node, where, "expected a number");
                double value = 0.0;
                if (!node.toDouble(value))
                    fail(node, where, "'" + node.scalar() + "' is not a number");
                if (!std::isfinite(value))
                    fail(node, where, "value '" + node.scalar() + "' is not finite");
                return value;
            }

            std::string string(const YamlNode &node, const std::string &where) const
            {
                if (!node.isScalar())
                    fail(node, where, "expected a string");
                return node.scalar();
            }

            /// [x, y, z] or {x: .., y: .., z: ..}
            Eigen::Vector3d vector3(const YamlNode &node, const std::string &where) const
            {
                Eigen::Vector3d v;
                if (node.isSequence())
                {
                    if (node.size() != 3)
                        fail(node, where, "expected 3 values, got " + std::to_string(node.size()));
                    for (std::size_t i = 0; i < 3; ++i)
                        v[int(i)] = number(node[i], where + "[" + std::to_string(i) + "]");
                }
                else if (node.isMap())
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
            Eigen::Quaterniond quaternion(const YamlNode &node, const std::string &where) const
            {
                double c[4];
                if (node.isSequence())
                {
                    if (node.size() != 4)
                        fail(node, where,
                             "expected a quaternion [x, y, z, w] (4 values), got " + std::to_string(node.size()) +
                                 " values");
                    for (std::size_t i = 0; i < 4; ++i)
                        c[i] = number(node[i], where + "[" + std::to_string(i) + "]");
                }
                else if (node.isMap())
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

            Eigen::Isometry3d pose(const YamlNode &node, const std::string &where) const
            {
                if (!node.isMap())
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

        bool nonEmpty(const YamlNode &node)
        {
            return node.isDefined() && !node.isNull() && !(node.isSequence() && node.size() == 0);
        }

        /// one primitive (shape_msgs/SolidPrimitive) with its pose in the object frame
        Shape readPrimitive(const Reader &reader, const YamlNode &node, const Eigen::Isometry3d &pose,
                            const std::string &where)
        {
            const YamlNode typeNode = reader.child(node, "type", where);
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
                    "unsupported primitive type '" + typeNode.scalar() + "' (expected box, sphere or cylinder)");

            const YamlNode dims = reader.sequence(reader.child(node, "dimensions", where), where + ".dimensions");
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
        std::vector<Shape> readShapes(const Reader &reader, const YamlNode &node, const std::string &at)
        {
            const YamlNode primitives = reader.sequence(reader.child(node, "primitives", at), at + ".primitives");
            const YamlNode poses = reader.sequence(reader.child(node, "primitive_poses", at), at + ".primitive_poses");
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
        std::string objectId(const Reader &reader, const YamlNode &node, const std::string &where,
                             std::set<std::string> &ids)
        {
            const YamlNode idNode = reader.child(node, "id", where);
            const std::string id = reader.string(idNode, where + ".id");
            if (id.empty())
                reader.fail(idNode, where + ".id", "empty object id");
            const std::string at = where + " '" + id + "'";
            if (!ids.insert(id).second)
                reader.fail(idNode, at, "duplicate object id '" + id + "'");
            return id;
        }

        void readCollisionObject(const Reader &reader, const YamlNode &node, const std::string &where,
                                 std::set<std::string> &ids, Environment &env)
        {
            if (!node.isMap())
                reader.fail(node, where,
                            "expected a collision object (a mapping with id, primitives, primitive_poses)");
            const std::string id = objectId(reader, node, where, ids);
            const std::string at = where + " '" + id + "'";

            if (const YamlNode op = node["operation"]; op.isDefined() && !op.isNull())
            {
                const std::string text = lower(reader.string(op, at + ".operation"));
                // CollisionObject constants: ADD = 0, REMOVE = 1, APPEND = 2, MOVE = 3
                if (text != "0" && text != "add")
                    reader.fail(op, at + ".operation",
                                "only ADD (0) is supported in a scene, got '" + op.scalar() + "'");
            }
            for (const char *unsupported : {"meshes", "planes"})
            {
                if (nonEmpty(node[unsupported]))
                    reader.fail(
                        node[unsupported], at + "." + unsupported,
                        std::string(unsupported) + " are not supported (box, sphere and cylinder primitives only)");
            }

            Eigen::Isometry3d objectPose = Eigen::Isometry3d::Identity();
            if (const YamlNode p = node["pose"]; p.isDefined() && !p.isNull())
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
        void readAttachedObject(const Reader &reader, const YamlNode &node, const std::string &where,
                                std::set<std::string> &ids, const std::shared_ptr<const RobotModel> &robot,
                                Environment &env)
        {
            if (!node.isMap())
                reader.fail(node, where, "expected an attached collision object (a mapping with link_name, object)");
            const std::string link = reader.string(reader.child(node, "link_name", where), where + ".link_name");
            const YamlNode object = reader.child(node, "object", where);
            if (!object.isMap())
                reader.fail(object, where + ".object", "expected a collision object (id, primitives, primitive_poses)");
            const YamlNode idNode = reader.child(object, "id", where + ".object");
            const std::string id = reader.string(idNode, where + ".object.id");
            if (id.empty())
                reader.fail(idNode, where + ".object.id", "empty object id");
            const std::string at = where + " '" + id + "'";
            if (!ids.insert(id).second)
                reader.fail(idNode, at, "duplicate object id '" + id + "'");
            if (!robot)
                reader.fail(node, at,
                            "attached collision objects need the robot model (load the scene with the robot)");
            if (const YamlNode header = object["header"]; header.isMap() && header["frame_id"].isDefined())
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
            if (const YamlNode p = object["pose"]; p.isDefined() && !p.isNull())
                body.pose = reader.pose(p, at + ".object.pose");
            body.shapes = readShapes(reader, object, at + ".object");
            if (const YamlNode touch = node["touch_links"]; touch.isDefined() && !touch.isNull())
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

        void readAttachedObjects(const Reader &reader, const YamlNode &root, std::set<std::string> &ids,
                                 const std::shared_ptr<const RobotModel> &robot, Environment &env)
        {
            const YamlNode state = root["robot_state"];
            if (!state.isDefined() || state.isNull())
                return;
            if (!state.isMap())
                reader.fail(state, "robot_state", "expected a mapping");
            const YamlNode attached = state["attached_collision_objects"];
            if (!attached.isDefined() || attached.isNull())
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
        void readPointCloud(const Reader &reader, const YamlNode &node, const std::string &where,
                            std::set<std::string> &ids, Environment &env)
        {
            if (!node.isMap())
                reader.fail(node, where, "expected a point cloud (a mapping with id, file, point_radius, pose)");
            const std::string id = objectId(reader, node, where, ids);
            const std::string at = where + " '" + id + "'";
            const YamlNode fileNode = reader.child(node, "file", at);
            std::filesystem::path file = reader.string(fileNode, at + ".file");
            if (file.is_relative())
                file = std::filesystem::path(reader.source()).parent_path() / file;
            double radius = 0.0;
            if (const YamlNode r = node["point_radius"]; r.isDefined() && !r.isNull())
            {
                radius = reader.number(r, at + ".point_radius");
                if (radius < 0.0 || radius > 1e3)
                    reader.fail(r, at + ".point_radius", "must be in [0, 1000] m, got " + r.scalar());
            }
            Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
            if (const YamlNode p = node["pose"]; p.isDefined() && !p.isNull())
                pose = reader.pose(p, at + ".pose");
            PointCloudFileOptions options;
            if (const YamlNode d = node["drop_non_finite"]; d.isDefined() && !d.isNull())
            {
                const std::string text = lower(reader.string(d, at + ".drop_non_finite"));
                if (text != "true" && text != "false")
                    reader.fail(d, at + ".drop_non_finite", "expected true or false, got '" + d.scalar() + "'");
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

        /** \brief The scene of \a yaml: each object of world.collision_objects is read (and added to the
            environment) as soon as the parser has passed it, then dropped from the tree; the rest of the document is
            checked when it has been read. */
        Environment readScene(const Reader &reader, const std::string &yaml,
                              const std::shared_ptr<const RobotModel> &robot)
        {
            Environment env;
            std::set<std::string> ids;
            const auto readObject = [&](const YamlNode &object, std::size_t i)
            { readCollisionObject(reader, object, "world.collision_objects[" + std::to_string(i) + "]", ids, env); };
            const YamlTree tree(yaml, reader.source(), {"world", "collision_objects"}, readObject);
            const YamlNode root = tree.root();
            if (!root.isMap())
                reader.fail(root, "document", "expected a MoveIt PlanningScene (a mapping with 'world')");
            const YamlNode world = root["world"];
            if (!world.isDefined())
                reader.fail(root, "document", "no 'world' key: not a MoveIt PlanningScene");
            if (!world.isNull())
            {
                if (!world.isMap())
                    reader.fail(world, "world", "expected a mapping with 'collision_objects'");
                const YamlNode objects = world["collision_objects"];
                if (objects.isDefined() && !objects.isNull())
                {
                    reader.sequence(objects, "world.collision_objects");
                    for (std::size_t i = 0; i < objects.size(); ++i)
                        if (!objects[i].isReleased())  // every item is read while parsing; kept for safety
                            readObject(objects[i], i);
                }
                if (const YamlNode clouds = world["point_clouds"]; clouds.isDefined() && !clouds.isNull())
                {
                    reader.sequence(clouds, "world.point_clouds");
                    for (std::size_t i = 0; i < clouds.size(); ++i)
                        readPointCloud(reader, clouds[i], "world.point_clouds[" + std::to_string(i) + "]", ids, env);
                }
            }
            readAttachedObjects(reader, root, ids, robot, env);
            return env;
        }

        MotionPlanRequest readRequest(const Reader &reader, const YamlNode &root)
        {
            if (!root.isMap())
                reader.fail(root, "document", "expected a MoveIt MotionPlanRequest (a mapping)");
            MotionPlanRequest request;

            const YamlNode startState = reader.child(root, "start_state", "document");
            const YamlNode jointState = reader.child(startState, "joint_state", "start_state");
            const YamlNode names = reader.sequence(reader.child(jointState, "name", "start_state.joint_state"),
                                                   "start_state.joint_state.name");
            const YamlNode positions = reader.sequence(reader.child(jointState, "position", "start_state.joint_state"),
                                                       "start_state.joint_state.position");
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

            const YamlNode goals =
                reader.sequence(reader.child(root, "goal_constraints", "document"), "goal_constraints");
            if (goals.size() == 0)
                reader.fail(goals, "goal_constraints", "no goal constraints");
            const YamlNode joints = reader.sequence(reader.child(goals[0], "joint_constraints", "goal_constraints[0]"),
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
            if (const YamlNode group = root["group_name"]; group.isDefined() && !group.isNull())
                request.group = reader.string(group, "group_name");
            return request;
        }
    }  // namespace

    Environment planningSceneFromString(const std::string &yaml, const std::string &sourceName,
                                        std::shared_ptr<const RobotModel> robot)
    {
        return readScene(Reader(sourceName), yaml, robot);
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
        const YamlTree tree(yaml, sourceName);
        return readRequest(reader, tree.root());
    }

    MotionPlanRequest loadMotionPlanRequest(const std::string &path)
    {
        return motionPlanRequestFromString(readInputFile(path, "request"), path);
    }
}  // namespace ropras::ompl_ext
