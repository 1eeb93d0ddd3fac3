// GCC 12 reports a false -Wmaybe-uninitialized inside Eigen's AVX-512 4x4 products (-march=native builds).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "model/RobotModelBuilder.h"

#include <tinyxml2.h>
#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <locale>
#include <sstream>

#include "model/ModelText.h"
#include "model/UrdfPose.h"
#include "model/UrdfSanity.h"

namespace ropras::ompl_ext
{
    namespace
    {
        using model_text::fmt;
        using model_text::joinNames;
        using urdf_pose::finitePose;
        using urdf_pose::jointMotion;
        using urdf_pose::toIsometry;
    }  // namespace

    std::shared_ptr<const RobotModel> RobotModelBuilder::build(const std::string &urdfXml, const std::string &srdfXml)
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

    void RobotModelBuilder::checkBasePose() const
    {
        const Eigen::Isometry3d &t = options_.basePose;
        const Eigen::Matrix3d r = t.linear();
        if (!finitePose(t) || (r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-6 || r.determinant() < 0.0)
        {
            fail("Options::basePose must be a finite rigid transform (orthonormal rotation)");
        }
        model_->basePose_ = t;
    }

    // urdfdom keeps joints in a name-sorted map: the URDF document order comes from tinyxml2. Unsupported
    // joint types are reported here, with the joint's name.
    void RobotModelBuilder::readDocumentOrder(const std::string &urdfXml)
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

    void RobotModelBuilder::checkCollisionNumbers(const std::string &link, int element,
                                                  const tinyxml2::XMLElement *collision) const
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

    void RobotModelBuilder::buildLinksAndJoints(const urdf::ModelInterface &urdf)
    {
        const std::map<std::string, int> linkIndex = orderLinks(urdf);
        model_->urdfJoints_.resize(jointOrder_.size());
        for (std::size_t i = 0; i < jointOrder_.size(); ++i)
        {
            readJoint(urdf, i, linkIndex);
        }
    }

    std::map<std::string, int> RobotModelBuilder::orderLinks(const urdf::ModelInterface &urdf)
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
        return linkIndex;
    }

    void RobotModelBuilder::readJoint(const urdf::ModelInterface &urdf, std::size_t i,
                                      const std::map<std::string, int> &linkIndex)
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

    // Fold fixed and held joints into the parent frame; every planned joint opens a frame that moves about
    // or along its local z: offset = (link in parent frame) * origin * A, with A mapping z onto the axis.
    void RobotModelBuilder::compileFrames()
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
}  // namespace ropras::ompl_ext
