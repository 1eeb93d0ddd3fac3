// GCC 12 reports a false -Wmaybe-uninitialized inside Eigen's AVX-512 4x4 products (-march=native builds).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "ropras/ompl_ext/model/RobotModel.h"

#include <tinyxml2.h>
#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <locale>
#include <random>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "model/EnclosingSphere.h"
#include "model/JointValues.h"
#include "model/SrdfGroups.h"
#include "model/SrdfReader.h"
#include "model/UrdfSanity.h"
#include "ropras/core/Error.h"
#include "ropras/core/InputFile.h"
#include "ropras/ompl_ext/model/MeshLoader.h"

namespace ropras::ompl_ext
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;

        Eigen::Isometry3d toIsometry(const urdf::Pose &pose)
        {
            Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
            t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
            t.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                             .normalized()
                             .toRotationMatrix();
            return t;
        }

        std::string fmt(double v)
        {
            std::ostringstream ss;
            ss.precision(10);
            ss << v;
            return ss.str();
        }

        std::string joinNames(const std::vector<std::string> &names)
        {
            std::string out;
            for (const std::string &n : names)
            {
                out += (out.empty() ? "" : ", ") + n;
            }
            return out.empty() ? std::string("(none)") : out;
        }

        /// the motion of a URDF joint at value v, in the joint frame
        Eigen::Isometry3d jointMotion(JointType type, const Eigen::Vector3d &axis, double v)
        {
            Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
            if (type == JointType::Revolute || type == JointType::Continuous)
            {
                m.linear() = Eigen::AngleAxisd(v, axis).toRotationMatrix();
            }
            else if (type == JointType::Prismatic)
            {
                m.translation() = axis * v;
            }
            return m;
        }

        bool finitePose(const Eigen::Isometry3d &t)
        {
            return t.matrix().allFinite();
        }
    }  // namespace

    /** \brief Builds a RobotModel from URDF (+ SRDF) text; the one place allowed to fill its members. */
    class RobotModelBuilder
    {
    public:
        RobotModelBuilder(const std::string &baseDir, const std::string &urdfName, const std::string &srdfName,
                          const RobotModel::Options &options)
            : model_(new RobotModel()), urdfName_(urdfName), srdfName_(srdfName), options_(options)
        {
            model_->source_ = urdfName;
            model_->baseDir_ = baseDir;
        }

        std::shared_ptr<const RobotModel> build(const std::string &urdfXml, const std::string &srdfXml)
        {
            checkBasePose();
            if (!std::isfinite(options_.limitTolerance) || options_.limitTolerance < 0.0)
                throw Error("RobotModel::Options::limitTolerance " + fmt(options_.limitTolerance) +
                            " must be finite and >= 0");
            model_->limitTolerance_ = options_.limitTolerance;
            model_->strict_ = options_.strict;
            hasSrdf_ = !srdfXml.empty();
            if (hasSrdf_)
            {
                srdf_ = readSrdf(srdfXml, srdfName_);
                model_->warnings_ = srdf_.warnings;
            }
            readDocumentOrder(urdfXml);
            urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDF(urdfXml);
            if (!urdf || !urdf->getRoot())
            {
                throw Error("URDF '" + urdfName_ +
                            "': urdfdom cannot build a model from it (missing or inconsistent <link>/<joint> "
                            "elements, bad numbers or several root links; urdfdom's diagnostics are on stderr)");
            }
            model_->name_ = urdf->getName();
            buildLinksAndJoints(*urdf);
            choosePlanningJoints(*urdf);
            compileFrames();
            buildCollisionGeometry(*urdf);
            buildSelfPairs();
            findAlwaysAndDefaultPairs();
            return model_;
        }

    private:
        [[noreturn]] void fail(const std::string &what) const { throw Error("URDF '" + urdfName_ + "': " + what); }
        void failIf(const std::string &problem) const
        {
            if (!problem.empty())
                fail(problem);
        }

        void checkBasePose() const
        {
            const Eigen::Isometry3d &t = options_.basePose;
            const Eigen::Matrix3d r = t.linear();
            if (!finitePose(t) || (r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-6 ||
                r.determinant() < 0.0)
            {
                fail("Options::basePose must be a finite rigid transform (orthonormal rotation)");
            }
            model_->basePose_ = t;
        }

        // urdfdom keeps joints in a name-sorted map: the URDF document order comes from tinyxml2. Unsupported
        // joint types are reported here, with the joint's name.
        void readDocumentOrder(const std::string &urdfXml)
        {
            tinyxml2::XMLDocument doc;
            if (doc.Parse(urdfXml.c_str(), urdfXml.size()) != tinyxml2::XML_SUCCESS)
            {
                fail(std::string("malformed XML: ") + (doc.ErrorStr() ? doc.ErrorStr() : "?"));
            }
            const tinyxml2::XMLElement *robot = doc.RootElement();
            if (robot == nullptr || std::string(robot->Name()) != "robot")
            {
                fail("the root element must be <robot>");
            }
            for (const tinyxml2::XMLElement *j = robot->FirstChildElement("joint"); j != nullptr;
                 j = j->NextSiblingElement("joint"))
            {
                const char *name = j->Attribute("name");
                const char *type = j->Attribute("type");
                if (name == nullptr)
                {
                    fail("a <joint> on line " + std::to_string(j->GetLineNum()) + " has no name");
                }
                const std::string t = type ? type : "";
                if (t == "floating" || t == "planar")
                {
                    fail("joint '" + std::string(name) + "' has type '" + t +
                         "'; only fixed, revolute, continuous and prismatic joints are supported");
                }
                if (t != "fixed" && t != "revolute" && t != "continuous" && t != "prismatic")
                {
                    fail("joint '" + std::string(name) + "' has unknown type '" + t + "'");
                }
                jointOrder_.emplace_back(name);
            }
            for (const tinyxml2::XMLElement *l = robot->FirstChildElement("link"); l != nullptr;
                 l = l->NextSiblingElement("link"))
            {
                const char *name = l->Attribute("name");
                if (name == nullptr)
                {
                    fail("a <link> on line " + std::to_string(l->GetLineNum()) + " has no name");
                }
                int element = 0;
                for (const tinyxml2::XMLElement *c = l->FirstChildElement("collision"); c != nullptr;
                     c = c->NextSiblingElement("collision"))
                {
                    ++element;
                    checkCollisionNumbers(name, element, c);
                }
                collisionCount_[name] = element;
            }
        }

        /// urdfdom drops a <collision> whose numbers do not parse (and only logs it): check them here
        void checkCollisionNumbers(const std::string &link, int element, const tinyxml2::XMLElement *collision) const
        {
            const tinyxml2::XMLElement *geometry = collision->FirstChildElement("geometry");
            const tinyxml2::XMLElement *shape = geometry ? geometry->FirstChildElement() : nullptr;
            if (shape == nullptr)
            {
                fail("link '" + link + "' <collision> #" + std::to_string(element) + " has no <geometry> shape");
            }
            const std::string type = shape->Name();
            auto check = [&](const char *attribute, int count)
            {
                const char *text = shape->Attribute(attribute);
                const std::string where =
                    "link '" + link + "' <collision> #" + std::to_string(element) + ": " + type + " " + attribute;
                if (text == nullptr)
                {
                    fail(where + " is missing");
                }
                std::istringstream in(text);
                in.imbue(std::locale::classic());
                for (int i = 0; i < count; ++i)
                {
                    std::string token;
                    in >> token;
                    char *end = nullptr;
                    const double v = std::strtod(token.c_str(), &end);
                    if (token.empty() || end == nullptr || *end != '\0' || !std::isfinite(v) ||
                        (type != "mesh" && v <= 0.0) || (type == "mesh" && v == 0.0))
                    {
                        fail(where + " '" + text + "' must hold " + std::to_string(count) +
                             (type == "mesh" ? " finite non-zero" : " positive finite") + " number(s)");
                    }
                }
            };
            if (type == "sphere")
            {
                check("radius", 1);
            }
            else if (type == "cylinder")
            {
                check("radius", 1);
                check("length", 1);
            }
            else if (type == "box")
            {
                check("size", 3);
            }
            else if (type == "mesh")
            {
                if (shape->Attribute("scale") != nullptr)
                {
                    check("scale", 3);
                }
            }
            else
            {
                fail("link '" + link + "' <collision> #" + std::to_string(element) + ": unsupported geometry <" + type +
                     ">");
            }
        }

        void buildLinksAndJoints(const urdf::ModelInterface &urdf)
        {
            // joints in document order
            std::map<std::string, int> jointIndex;
            for (const std::string &name : jointOrder_)
            {
                if (jointIndex.count(name) != 0)
                {
                    fail("joint '" + name + "' is defined twice");
                }
                const int idx = static_cast<int>(jointIndex.size());
                jointIndex[name] = idx;
            }
            if (jointIndex.size() != urdf.joints_.size())
            {
                fail("urdfdom and the XML disagree on the number of joints");
            }

            // links in depth-first topological order from the root, children in joint document order
            std::map<std::string, std::vector<std::string>> childJoints;  // parent link -> joints
            for (const std::string &name : jointOrder_)
            {
                const auto it = urdf.joints_.find(name);
                if (it == urdf.joints_.end())
                {
                    fail("joint '" + name + "' was not accepted by urdfdom");
                }
                childJoints[it->second->parent_link_name].push_back(name);
            }
            std::map<std::string, int> linkIndex;
            std::vector<std::string> stack{urdf.getRoot()->name};
            while (!stack.empty())
            {
                const std::string linkName = stack.back();
                stack.pop_back();
                if (linkIndex.count(linkName) != 0)
                {
                    fail("link '" + linkName + "' is reached twice (the links do not form a tree)");
                }
                Link link;
                link.name = linkName;
                linkIndex[linkName] = static_cast<int>(model_->links_.size());
                model_->links_.push_back(link);
                const auto children = childJoints.find(linkName);
                if (children != childJoints.end())
                {
                    for (auto j = children->second.rbegin(); j != children->second.rend(); ++j)
                    {
                        stack.push_back(urdf.joints_.at(*j)->child_link_name);
                    }
                }
            }
            if (model_->links_.size() != urdf.links_.size())
            {
                fail("some links are not connected to the root link '" + urdf.getRoot()->name + "'");
            }

            model_->urdfJoints_.resize(jointOrder_.size());
            for (std::size_t i = 0; i < jointOrder_.size(); ++i)
            {
                const urdf::Joint &uj = *urdf.joints_.at(jointOrder_[i]);
                UrdfJoint &j = model_->urdfJoints_[i];
                j.name = uj.name;
                switch (uj.type)
                {
                    case urdf::Joint::FIXED:
                        j.type = JointType::Fixed;
                        break;
                    case urdf::Joint::REVOLUTE:
                        j.type = JointType::Revolute;
                        break;
                    case urdf::Joint::CONTINUOUS:
                        j.type = JointType::Continuous;
                        break;
                    case urdf::Joint::PRISMATIC:
                        j.type = JointType::Prismatic;
                        break;
                    default:
                        fail("joint '" + uj.name + "' has an unsupported type");
                }
                j.parentLink = linkIndex.at(uj.parent_link_name);
                j.childLink = linkIndex.at(uj.child_link_name);
                j.origin = toIsometry(uj.parent_to_joint_origin_transform);
                if (!finitePose(j.origin))
                {
                    fail("joint '" + uj.name + "' has a non-finite <origin>");
                }
                failIf(urdf_sanity::originProblem("joint '" + uj.name + "' <origin>", j.origin));
                failIf(urdf_sanity::mimicProblem(urdf, uj));
                if (j.type != JointType::Fixed)
                {
                    const Eigen::Vector3d axis(uj.axis.x, uj.axis.y, uj.axis.z);
                    if (!axis.allFinite() || axis.norm() < 1e-9)
                    {
                        fail("joint '" + uj.name + "' has a zero or non-finite <axis>");
                    }
                    j.axis = axis.normalized();
                }
                model_->links_[j.childLink].parentJoint = static_cast<int>(i);
            }
        }

        void choosePlanningJoints(const urdf::ModelInterface &urdf)
        {
            auto &joints = model_->urdfJoints_;
            std::vector<std::string> candidates;  // movable, non-mimic joints in document order
            for (const UrdfJoint &j : joints)
            {
                if (j.type != JointType::Fixed && !urdf.joints_.at(j.name)->mimic)
                {
                    candidates.push_back(j.name);
                }
            }
            auto findJoint = [&](const std::string &name) -> int
            {
                for (std::size_t i = 0; i < joints.size(); ++i)
                {
                    if (joints[i].name == name)
                    {
                        return static_cast<int>(i);
                    }
                }
                return -1;
            };

            // joint limits (planning joints and held joints alike)
            std::vector<double> lower(joints.size(), 0.0), upper(joints.size(), 0.0);
            for (std::size_t i = 0; i < joints.size(); ++i)
            {
                const urdf::Joint &uj = *urdf.joints_.at(joints[i].name);
                if (joints[i].type == JointType::Continuous)
                {
                    lower[i] = -PI;
                    upper[i] = PI;
                }
                else if (joints[i].type != JointType::Fixed)
                {
                    if (!uj.limits)
                    {
                        fail("joint '" + uj.name + "' has no <limit>");
                    }
                    lower[i] = uj.limits->lower;
                    upper[i] = uj.limits->upper;
                    if (!std::isfinite(lower[i]) || !std::isfinite(upper[i]) || lower[i] > upper[i])
                    {
                        fail("joint '" + uj.name + "' has invalid limits [" + fmt(lower[i]) + ", " + fmt(upper[i]) +
                             "]");
                    }
                    failIf(urdf_sanity::limitProblem(uj.name, joints[i].type, lower[i], upper[i]));
                }
            }

            resolveGroups(candidates);
            std::vector<std::string> chosen = chosenJoints(candidates);
            std::set<std::string> seen;
            for (const std::string &name : chosen)
            {
                const int idx = findJoint(name);
                if (idx < 0 || std::find(candidates.begin(), candidates.end(), name) == candidates.end())
                {
                    std::string why = idx < 0                                ? "is not a joint of the URDF"
                                      : joints[idx].type == JointType::Fixed ? "is a fixed joint"
                                                                             : "is a mimic joint";
                    fail("planning joint '" + name + "' " + why + "; valid planning joints: " + joinNames(candidates));
                }
                if (!seen.insert(name).second)
                {
                    fail("planning joint '" + name + "' is listed twice");
                }
                PlanningJoint pj;
                pj.name = name;
                pj.type = joints[idx].type;
                pj.lower = lower[idx];
                pj.upper = upper[idx];
                pj.urdfJoint = idx;
                joints[idx].variable = static_cast<int>(model_->joints_.size());
                model_->joints_.push_back(pj);
            }
            holdJoints(lower, upper, findJoint);
        }

        /// model_->groups_: every SRDF group that resolves (a group that does not is a warning, or with
        /// Options::strict an error)
        void resolveGroups(const std::vector<std::string> &candidates)
        {
            for (const SrdfGroup &group : srdf_.groups)
            {
                try
                {
                    std::vector<std::string> &movable = model_->groups_[group.name];
                    for (const int j :
                         srdfGroupJoints(srdf_, group.name, model_->links_, model_->urdfJoints_, srdfName_))
                    {
                        const std::string &name = model_->urdfJoints_[j].name;
                        if (std::find(candidates.begin(), candidates.end(), name) != candidates.end())
                            movable.push_back(name);
                    }
                }
                catch (const Error &e)
                {
                    model_->groups_.erase(group.name);
                    if (options_.strict || group.name == options_.group)
                        throw;
                    model_->warnings_.push_back(std::string(e.what()) + "; the group is skipped");
                }
            }
        }

        /// the planning joints by name: Options::planningJoints, Options::group's, or every candidate
        std::vector<std::string> chosenJoints(const std::vector<std::string> &candidates)
        {
            std::string group = options_.group;
            if (group.empty() && options_.planningJoints.empty() && model_->groups_.count(options_.requestGroup))
                group = options_.requestGroup;
            if (group.empty())
                return options_.planningJoints.empty() ? candidates : options_.planningJoints;
            if (!options_.planningJoints.empty())
                fail("give the planning joints or a planning group ('" + group + "'), not both");
            if (srdf_.groups.empty())
                fail("planning group '" + group + "' needs an SRDF that defines groups" +
                     (hasSrdf_ ? " ('" + srdfName_ + "' defines none)" : std::string(" (no SRDF given)")));
            if (model_->groups_.count(group) == 0)  // not defined: the resolver's message lists the groups
                srdfGroupJoints(srdf_, group, model_->links_, model_->urdfJoints_, srdfName_);
            const std::vector<std::string> &joints = model_->groups_.at(group);
            if (joints.empty())
                fail("planning group '" + group + "' of SRDF '" + srdfName_ + "' has no movable joint");
            model_->group_ = group;
            return joints;
        }

        /// held joints: default 0 clamped into the limits, Options::jointState's value, or Options::heldJointValues'
        template <typename FindJoint>
        void holdJoints(const std::vector<double> &lower, const std::vector<double> &upper, const FindJoint &findJoint)
        {
            auto &joints = model_->urdfJoints_;
            for (std::size_t i = 0; i < joints.size(); ++i)
            {
                if (joints[i].type != JointType::Fixed && joints[i].variable < 0)
                {
                    joints[i].heldValue = std::clamp(0.0, lower[i], upper[i]);
                }
            }
            std::vector<std::string> unknown;
            for (const auto &[name, value] : options_.jointState)
            {
                const int idx = findJoint(name);
                if (idx < 0)
                    unknown.push_back(name);
                else if (joints[idx].type != JointType::Fixed && joints[idx].variable < 0 &&
                         options_.heldJointValues.count(name) == 0)
                    holdJoint(idx, value, lower[idx], upper[idx], "the joint state's");
            }
            if (!unknown.empty())
            {
                const std::string what = "the joint state names joints the URDF does not have: " + joinNames(unknown);
                if (options_.strict)
                    fail(what);
                model_->warnings_.push_back("URDF '" + urdfName_ + "': " + what + "; they are ignored");
            }
            for (const auto &[name, value] : options_.heldJointValues)
            {
                const int idx = findJoint(name);
                if (idx < 0)
                {
                    std::vector<std::string> movable;
                    for (const UrdfJoint &j : joints)
                    {
                        if (j.type != JointType::Fixed)
                        {
                            movable.push_back(j.name);
                        }
                    }
                    fail("held joint '" + name + "' is not a joint of the URDF; movable joints: " + joinNames(movable));
                }
                if (joints[idx].type == JointType::Fixed)
                {
                    fail("held joint '" + name + "' is a fixed joint");
                }
                if (joints[idx].variable >= 0)
                {
                    fail("held joint '" + name + "' is a planning joint; give values only for joints not planned");
                }
                holdJoint(idx, value, lower[idx], upper[idx], "held joint");
            }
        }

        /// holds URDF joint \a idx at \a value, clamped within Options::limitTolerance (unless strict)
        void holdJoint(int idx, double value, double lower, double upper, const std::string &what)
        {
            UrdfJoint &joint = model_->urdfJoints_[idx];
            if (!options_.strict)
            {
                const std::string warning =
                    fitJointValue(joint.name, joint.type, lower, upper, options_.limitTolerance, value);
                if (!warning.empty())
                    model_->warnings_.push_back("URDF '" + urdfName_ + "': held " + warning);
            }
            const bool inLimits = joint.type == JointType::Continuous
                                      ? std::isfinite(value)
                                      : (std::isfinite(value) && value >= lower && value <= upper);
            if (!inLimits)
            {
                fail(what + " '" + joint.name + "' value " + fmt(value) + " is outside its limits [" + fmt(lower) +
                     ", " + fmt(upper) + "]");
            }
            joint.heldValue = value;
        }

        // Fold fixed and held joints into the parent frame; every planned joint opens a frame that moves about
        // or along its local z: offset = (link in parent frame) * origin * A, with A mapping z onto the axis.
        void compileFrames()
        {
            auto &links = model_->links_;
            auto &frames = model_->frames_;
            KinematicFrame root;
            root.name = links[0].name;
            root.offset = model_->basePose_;
            frames.push_back(root);
            links[0].frame = 0;
            links[0].inFrame = Eigen::Isometry3d::Identity();
            for (std::size_t li = 1; li < links.size(); ++li)
            {
                Link &link = links[li];
                const UrdfJoint &j = model_->urdfJoints_[link.parentJoint];
                const Link &parent = links[j.parentLink];
                if (j.variable < 0)
                {
                    link.frame = parent.frame;
                    link.inFrame = parent.inFrame * j.origin * jointMotion(j.type, j.axis, j.heldValue);
                    continue;
                }
                const Eigen::Matrix3d a =
                    Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), j.axis).toRotationMatrix();
                Eigen::Isometry3d aIso = Eigen::Isometry3d::Identity();
                aIso.linear() = a;
                KinematicFrame f;
                f.name = link.name;
                f.parent = parent.frame;
                f.variable = j.variable;
                f.motion = j.type == JointType::Prismatic ? JointMotion::TranslateZ : JointMotion::RotateZ;
                f.offset = parent.inFrame * j.origin * aIso;
                link.frame = static_cast<int>(frames.size());
                link.inFrame = Eigen::Isometry3d::Identity();
                link.inFrame.linear() = a.transpose();
                frames.push_back(f);
            }
        }

        void checkPositive(double v, const std::string &what, const std::string &link, int element) const
        {
            if (!std::isfinite(v) || v <= 0.0)
            {
                fail("link '" + link + "' <collision> #" + std::to_string(element) + ": " + what + " " + fmt(v) +
                     " must be positive and finite");
            }
            failIf(urdf_sanity::sizeProblem("link '" + link + "' <collision> #" + std::to_string(element) + ": " + what,
                                            v, what == "mesh scale"));
        }

        void buildCollisionGeometry(const urdf::ModelInterface &urdf)
        {
            std::map<std::string, SphereCover> meshCovers;  // "path|scale" -> cover in the mesh frame
            for (std::size_t li = 0; li < model_->links_.size(); ++li)
            {
                const Link &link = model_->links_[li];
                const urdf::Link &ul = *urdf.links_.at(link.name);
                if (static_cast<int>(ul.collision_array.size()) != collisionCount_[link.name])
                {
                    fail("link '" + link.name + "': urdfdom accepted " + std::to_string(ul.collision_array.size()) +
                         " of its " + std::to_string(collisionCount_[link.name]) + " <collision> elements");
                }
                std::vector<Sphere> linkSpheres;
                int element = 0;
                for (const urdf::CollisionSharedPtr &c : ul.collision_array)
                {
                    ++element;
                    if (!c || !c->geometry)
                    {
                        continue;
                    }
                    CollisionGeometry g;
                    g.link = static_cast<int>(li);
                    g.origin = toIsometry(c->origin);
                    if (!finitePose(g.origin))
                    {
                        fail("link '" + link.name + "' <collision> #" + std::to_string(element) +
                             ": non-finite <origin>");
                    }
                    failIf(urdf_sanity::originProblem(
                        "link '" + link.name + "' <collision> #" + std::to_string(element) + " <origin>", g.origin));
                    SphereCover cover;
                    try
                    {
                        switch (c->geometry->type)
                        {
                            case urdf::Geometry::SPHERE:
                            {
                                g.type = CollisionGeometry::Type::Sphere;
                                g.radius = static_cast<const urdf::Sphere &>(*c->geometry).radius;
                                checkPositive(g.radius, "sphere radius", link.name, element);
                                cover.spheres.push_back(Sphere{Eigen::Vector3d::Zero(), g.radius});
                                break;
                            }
                            case urdf::Geometry::BOX:
                            {
                                const urdf::Vector3 &d = static_cast<const urdf::Box &>(*c->geometry).dim;
                                g.type = CollisionGeometry::Type::Box;
                                g.extents = Eigen::Vector3d(d.x, d.y, d.z);
                                for (int k = 0; k < 3; ++k)
                                {
                                    checkPositive(g.extents[k], "box size", link.name, element);
                                }
                                cover = spherizer::coverBoxDetailed(g.extents, options_.spherizer);
                                break;
                            }
                            case urdf::Geometry::CYLINDER:
                            {
                                const auto &cyl = static_cast<const urdf::Cylinder &>(*c->geometry);
                                g.type = CollisionGeometry::Type::Cylinder;
                                g.radius = cyl.radius;
                                g.length = cyl.length;
                                checkPositive(g.radius, "cylinder radius", link.name, element);
                                checkPositive(g.length, "cylinder length", link.name, element);
                                cover = spherizer::coverCylinderDetailed(g.radius, g.length, options_.spherizer);
                                break;
                            }
                            case urdf::Geometry::MESH:
                            {
                                const auto &mesh = static_cast<const urdf::Mesh &>(*c->geometry);
                                g.type = CollisionGeometry::Type::Mesh;
                                g.scale = Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z);
                                for (int k = 0; k < 3; ++k)
                                {
                                    checkPositive(std::abs(g.scale[k]), "mesh scale", link.name, element);
                                }
                                g.meshPath = resolveMeshPath(mesh.filename, model_->baseDir_, urdfName_);
                                std::ostringstream key;
                                key.precision(17);
                                key << g.meshPath << '|' << g.scale.x() << ',' << g.scale.y() << ',' << g.scale.z();
                                auto it = meshCovers.find(key.str());
                                if (it == meshCovers.end())
                                {
                                    const TriangleMesh tm = loadMesh(g.meshPath, g.scale);
                                    it = meshCovers
                                             .emplace(key.str(), spherizer::coverMeshDetailed(tm.vertices, tm.triangles,
                                                                                              options_.spherizer))
                                             .first;
                                }
                                cover = it->second;
                                break;
                            }
                            default:
                                fail("link '" + link.name + "' <collision> #" + std::to_string(element) +
                                     ": unsupported geometry");
                        }
                    }
                    catch (const Error &e)
                    {
                        const std::string msg = e.what();
                        if (msg.find(urdfName_) != std::string::npos)
                        {
                            throw;
                        }
                        fail("link '" + link.name + "' <collision> #" + std::to_string(element) + ": " + msg);
                    }
                    for (Sphere &s : cover.spheres)
                    {
                        s.center = g.origin * s.center;
                        linkSpheres.push_back(s);
                    }
                    g.coverProtrusion = cover.protrusion;
                    model_->geometries_.push_back(g);
                }
                if (linkSpheres.empty())
                {
                    continue;
                }
                CollisionLink cl;
                cl.name = link.name;
                cl.link = static_cast<int>(li);
                cl.frame = link.frame;
                cl.firstSphere = static_cast<int>(model_->spheres_.size());
                cl.sphereCount = static_cast<int>(linkSpheres.size());
                std::vector<Sphere> inFrame;
                for (const Sphere &s : linkSpheres)
                {
                    CollisionSphere cs;
                    cs.centerInLink = s.center;
                    cs.centerInFrame = link.inFrame * s.center;
                    cs.radius = s.radius;
                    cs.collisionLink = static_cast<int>(model_->collisionLinks_.size());
                    model_->spheres_.push_back(cs);
                    inFrame.push_back(Sphere{cs.centerInFrame, cs.radius});
                }
                // the refinement costs 2 x iterations x spheres: a link of 100 000 spheres gets 200 iterations
                // instead of 2000 (the bound still encloses every sphere exactly; it is only a little less tight)
                const int iterations =
                    inFrame.size() > 10000 ? std::max(200, static_cast<int>(2e7 / double(inFrame.size()))) : 2000;
                const Sphere bound = enclosingSphere(inFrame, iterations);
                cl.boundCenterInFrame = bound.center;
                cl.boundRadius = bound.radius;
                model_->collisionLinks_.push_back(cl);
            }
        }

        // Self-collision pairs: collision links on different compiled frames, minus SRDF disable_collisions,
        // minus adjacent links. Two links are adjacent when the tree path between them has at most one non-fixed
        // joint and every link strictly inside the path has no collision geometry (MoveIt's rule of
        // bridging geometry-less links).
        void buildSelfPairs()
        {
            const auto &links = model_->links_;
            std::vector<int> collisionOf(links.size(), -1);
            for (std::size_t i = 0; i < model_->collisionLinks_.size(); ++i)
            {
                collisionOf[model_->collisionLinks_[i].link] = static_cast<int>(i);
            }
            // pairs of link indices that are never checked: SRDF disable_collisions, Options::disabledPairs, and
            // adjacent links (hashed: the loop over all collision-link pairs below does O(1) work per pair)
            std::unordered_set<std::uint64_t> skipped;
            const auto key = [](int a, int b)
            { return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b)); };
            std::unordered_map<std::string, int> linkIndex;
            for (std::size_t i = 0; i < links.size(); ++i)
            {
                linkIndex.emplace(links[i].name, static_cast<int>(i));
            }
            std::map<std::string, std::string> unknownLines;  // unknown link -> the lines naming it
            std::vector<std::string> unknownOrder;
            for (const SrdfDisabledPair &pair : srdf_.disabledPairs)
            {
                const auto ia = linkIndex.find(pair.link1), ib = linkIndex.find(pair.link2);
                if (ia != linkIndex.end() && ib != linkIndex.end())
                {
                    skipped.insert(key(ia->second, ib->second));
                    continue;
                }
                const std::string &link = ia == linkIndex.end() ? pair.link1 : pair.link2;
                if (options_.strict)
                    throw Error("SRDF '" + srdfName_ + "': <disable_collisions> on line " + std::to_string(pair.line) +
                                " names link '" + link + "', which the URDF does not define");
                std::string &lines = unknownLines[link];
                if (lines.empty())
                    unknownOrder.push_back(link);
                lines += (lines.empty() ? "" : ", ") + std::to_string(pair.line);
            }
            // MoveIt warns and skips such entries: one SRDF often serves several variants of a robot
            for (const std::string &link : unknownOrder)
                model_->warnings_.push_back("SRDF '" + srdfName_ + "': <disable_collisions> on line" +
                                            (unknownLines[link].find(',') == std::string::npos ? " " : "s ") +
                                            unknownLines[link] + " names link '" + link +
                                            "', which the URDF does not define; skipped");
            for (const auto &[a, b] : options_.disabledPairs)
            {
                const auto ia = linkIndex.find(a), ib = linkIndex.find(b);
                if (ia == linkIndex.end() || ib == linkIndex.end())
                {
                    fail("Options::disabledPairs names unknown link '" + (ia == linkIndex.end() ? a : b) + "'");
                }
                skipped.insert(key(ia->second, ib->second));
            }
            std::vector<std::vector<int>> childJoints(links.size());
            for (std::size_t j = 0; j < model_->urdfJoints_.size(); ++j)
            {
                childJoints[static_cast<std::size_t>(model_->urdfJoints_[j].parentLink)].push_back(static_cast<int>(j));
            }
            for (std::size_t i = 0; i < model_->collisionLinks_.size(); ++i)
            {
                const int a = model_->collisionLinks_[i].link;
                for (const int b : adjacentLinks(a, collisionOf, childJoints))
                {
                    skipped.insert(key(a, b));
                }
            }
            const auto &cls = model_->collisionLinks_;
            for (std::size_t i = 0; i < cls.size(); ++i)
            {
                for (std::size_t k = i + 1; k < cls.size(); ++k)
                {
                    if (cls[i].frame != cls[k].frame && skipped.count(key(cls[i].link, cls[k].link)) == 0)
                    {
                        model_->selfPairs_.emplace_back(static_cast<int>(i), static_cast<int>(k));
                    }
                }
            }
        }

        /** \brief The links with collision geometry adjacent to link \a from: the tree path between them has at
            most one non-fixed joint and every link strictly inside it has no collision geometry. Found by a walk
            from \a from that stops at geometry and at a second non-fixed joint, so its cost is the size of that
            neighbourhood (not the depth of the tree for every pair of links). */
        std::vector<int> adjacentLinks(int from, const std::vector<int> &collisionOf,
                                       const std::vector<std::vector<int>> &childJoints) const
        {
            const auto &links = model_->links_;
            const auto &joints = model_->urdfJoints_;
            std::vector<int> out;
            struct Step
            {
                int link, previous, movable;
            };
            std::vector<Step> stack{{from, -1, 0}};
            while (!stack.empty())
            {
                const Step step = stack.back();
                stack.pop_back();
                if (step.link != from && collisionOf[static_cast<std::size_t>(step.link)] >= 0)
                {
                    out.push_back(step.link);  // an end point: the path does not continue through geometry
                    continue;
                }
                const auto visit = [&](int next, const UrdfJoint &joint)
                {
                    const int movable = step.movable + (joint.type != JointType::Fixed ? 1 : 0);
                    if (next != step.previous && movable <= 1)
                    {
                        stack.push_back({next, step.link, movable});
                    }
                };
                const Link &link = links[static_cast<std::size_t>(step.link)];
                if (link.parentJoint >= 0)
                {
                    const UrdfJoint &up = joints[static_cast<std::size_t>(link.parentJoint)];
                    visit(up.parentLink, up);
                }
                for (const int j : childJoints[static_cast<std::size_t>(step.link)])
                {
                    visit(joints[static_cast<std::size_t>(j)].childLink, joints[static_cast<std::size_t>(j)]);
                }
            }
            return out;
        }

        /// true when some sphere of collision link \a a touches (distance <= sum of radii) one of link \a b
        bool inContact(const std::vector<Eigen::Vector3d> &centers, int a, int b) const
        {
            const auto &spheres = model_->spheres_;
            const CollisionLink &la = model_->collisionLinks_[static_cast<std::size_t>(a)];
            const CollisionLink &lb = model_->collisionLinks_[static_cast<std::size_t>(b)];
            for (int i = la.firstSphere; i < la.firstSphere + la.sphereCount; ++i)
            {
                for (int j = lb.firstSphere; j < lb.firstSphere + lb.sphereCount; ++j)
                {
                    const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
                    if ((centers[si] - centers[sj]).norm() <= spheres[si].radius + spheres[sj].radius)
                    {
                        return true;
                    }
                }
            }
            return false;
        }

        std::pair<std::string, std::string> pairNames(const std::pair<int, int> &p) const
        {
            return {model_->collisionLinks_[static_cast<std::size_t>(p.first)].name,
                    model_->collisionLinks_[static_cast<std::size_t>(p.second)].name};
        }

        // MoveIt Setup Assistant's "Always" rule (disable pairs in contact in every sampled configuration) and
        // "Default" rule (report, but keep, pairs in contact at the default configuration). Samples are uniform
        // within the limits from a fixed-seed mt19937_64 with a portable [0, 1) mapping, so the result is the same
        // on every platform. A pair leaves the candidates at its first contact-free sample; sampling stops early
        // when none is left, which does not change the result.
        void findAlwaysAndDefaultPairs()
        {
            std::vector<std::pair<int, int>> &pairs = model_->selfPairs_;
            if (options_.disableAlwaysColliding)
            {
                if (options_.alwaysCollidingSamples == 0)
                {
                    fail("Options::alwaysCollidingSamples must be > 0 when disableAlwaysColliding is on");
                }
                std::vector<std::pair<int, int>> always = pairs;
                std::mt19937_64 rng(options_.alwaysCollidingSeed);
                std::vector<double> q(model_->joints_.size());
                for (std::size_t k = 0; k < options_.alwaysCollidingSamples && !always.empty(); ++k)
                {
                    for (std::size_t i = 0; i < q.size(); ++i)
                    {
                        const PlanningJoint &j = model_->joints_[i];
                        const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
                        q[i] = std::min(j.upper, j.lower + u * (j.upper - j.lower));
                    }
                    const std::vector<Eigen::Vector3d> centers = model_->sphereCentersReference(q.data());
                    always.erase(std::remove_if(always.begin(), always.end(),
                                                [&](const std::pair<int, int> &p)
                                                { return !inContact(centers, p.first, p.second); }),
                                 always.end());
                }
                for (const std::pair<int, int> &p : always)
                {
                    model_->alwaysPairs_.push_back(pairNames(p));
                }
                std::unordered_set<std::uint64_t> alwaysKeys;  // hashed: O(1) per pair, not O(|always|)
                for (const std::pair<int, int> &p : always)
                {
                    alwaysKeys.insert((std::uint64_t(std::uint32_t(p.first)) << 32) | std::uint32_t(p.second));
                }
                pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                                           [&](const std::pair<int, int> &p) {
                                               return alwaysKeys.count((std::uint64_t(std::uint32_t(p.first)) << 32) |
                                                                       std::uint32_t(p.second)) != 0;
                                           }),
                            pairs.end());
            }
            const std::vector<double> q = model_->defaultConfiguration();
            const std::vector<Eigen::Vector3d> centers = model_->sphereCentersReference(q.data());
            for (const std::pair<int, int> &p : pairs)
            {
                if (inContact(centers, p.first, p.second))
                {
                    model_->defaultPairs_.push_back(pairNames(p));
                }
            }
        }

        std::shared_ptr<RobotModel> model_;
        std::string urdfName_, srdfName_;
        const RobotModel::Options &options_;
        SrdfDocument srdf_;
        bool hasSrdf_{false};
        std::vector<std::string> jointOrder_;
        std::map<std::string, int> collisionCount_;
    };

    std::shared_ptr<const RobotModel> RobotModel::fromUrdfFile(const std::string &urdfPath, const std::string &srdfPath,
                                                               const Options &options)
    {
        const std::string urdfXml = readInputFile(urdfPath, "URDF");
        const std::string srdfXml = srdfPath.empty() ? std::string() : readInputFile(srdfPath, "SRDF");
        if (!srdfPath.empty() && srdfXml.find_first_not_of(" \t\r\n") == std::string::npos)
        {
            throw Error("SRDF '" + srdfPath + "': the file is empty");
        }
        std::error_code ec;
        const std::filesystem::path dir = std::filesystem::absolute(urdfPath, ec).parent_path();
        RobotModelBuilder builder(dir.string(), urdfPath, srdfPath, options);
        return builder.build(urdfXml, srdfXml);
    }

    std::shared_ptr<const RobotModel> RobotModel::fromUrdfString(const std::string &urdfXml, const std::string &baseDir,
                                                                 const std::string &sourceName,
                                                                 const std::string &srdfXml, const Options &options)
    {
        RobotModelBuilder builder(baseDir, sourceName, sourceName + " (SRDF)", options);
        return builder.build(urdfXml, srdfXml);
    }

    std::vector<double> RobotModel::planningValues(const std::map<std::string, double> &jointValues,
                                                   const std::string &context, std::vector<std::string> *warnings) const
    {
        std::vector<std::string> unknown;
        for (const auto &entry : jointValues)
            if (std::none_of(urdfJoints_.begin(), urdfJoints_.end(),
                             [&](const UrdfJoint &j) { return j.name == entry.first; }))
                unknown.push_back(entry.first);
        if (strict_ && !unknown.empty())
            throw Error(context + ": names joint '" + unknown.front() + "', which robot '" + name_ + "' (" + source_ +
                        ") does not have");
        if (!unknown.empty() && warnings)  // MoveIt ignores joints outside the planning group
            warnings->push_back(context + ": names joints robot '" + name_ + "' (" + source_ +
                                ") does not have, ignored: " + joinNames(unknown));
        std::vector<double> q(joints_.size());
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            auto it = jointValues.find(joints_[i].name);
            if (it == jointValues.end())
                throw Error(context + ": does not give planning joint '" + joints_[i].name + "'");
            q[i] = it->second;
            if (strict_)
                continue;
            const PlanningJoint &j = joints_[i];
            const std::string warning = fitJointValue(j.name, j.type, j.lower, j.upper, limitTolerance_, q[i]);
            if (!warning.empty() && warnings)
                warnings->push_back(context + ": " + warning);
        }
        return q;
    }

    int RobotModel::jointIndex(const std::string &name) const
    {
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            if (joints_[i].name == name)
            {
                return static_cast<int>(i);
            }
        }
        std::vector<std::string> names;
        for (const PlanningJoint &j : joints_)
        {
            names.push_back(j.name);
        }
        throw Error("robot '" + name_ + "' (" + source_ + "): no planning joint '" + name +
                    "'; planning joints: " + joinNames(names));
    }

    int RobotModel::linkIndex(const std::string &name) const
    {
        for (std::size_t i = 0; i < links_.size(); ++i)
        {
            if (links_[i].name == name)
            {
                return static_cast<int>(i);
            }
        }
        throw Error("robot '" + name_ + "' (" + source_ + "): no link '" + name + "'");
    }

    std::vector<double> RobotModel::defaultConfiguration() const
    {
        std::vector<double> q;
        q.reserve(joints_.size());
        for (const PlanningJoint &j : joints_)
        {
            q.push_back(std::clamp(0.0, j.lower, j.upper));
        }
        return q;
    }

    bool RobotModel::withinBounds(const double *q) const noexcept
    {
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            const double v = q[i];
            if (!std::isfinite(v))
            {
                return false;
            }
            if (joints_[i].type != JointType::Continuous && (v < joints_[i].lower || v > joints_[i].upper))
            {
                return false;
            }
        }
        return true;
    }

    std::vector<Eigen::Isometry3d> RobotModel::linkTransformsReference(const double *q) const
    {
        // links_ is in topological order (parents first), so one pass suffices.
        std::vector<Eigen::Isometry3d> out(links_.size(), Eigen::Isometry3d::Identity());
        for (std::size_t i = 0; i < links_.size(); ++i)
        {
            const int pj = links_[i].parentJoint;
            if (pj < 0)
            {
                out[i] = basePose_;
                continue;
            }
            const UrdfJoint &j = urdfJoints_[pj];
            const double v = j.variable >= 0 ? q[j.variable] : j.heldValue;
            out[i] = out[j.parentLink] * j.origin * jointMotion(j.type, j.axis, v);
        }
        return out;
    }

    std::vector<Eigen::Vector3d> RobotModel::sphereCentersReference(const double *q) const
    {
        const std::vector<Eigen::Isometry3d> t = linkTransformsReference(q);
        std::vector<Eigen::Vector3d> out;
        out.reserve(spheres_.size());
        for (const CollisionSphere &s : spheres_)
        {
            out.push_back(t[collisionLinks_[s.collisionLink].link] * s.centerInLink);
        }
        return out;
    }
}  // namespace ropras::ompl_ext
