#ifndef ROPRAS_OMPL_EXT_SRC_ROBOT_MODEL_BUILDER_H
#define ROPRAS_OMPL_EXT_SRC_ROBOT_MODEL_BUILDER_H

#include <tinyxml2.h>
#include <urdf_model/model.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "model/SrdfReader.h"
#include "ropras/core/Error.h"
#include "ropras/ompl_ext/model/RobotModel.h"
#include "ropras/ompl_ext/model/Spherizer.h"

namespace ropras::ompl_ext
{
    /** \brief Builds a RobotModel from URDF (+ SRDF) text; the one place allowed to fill its members. build() is a
        list of named steps, defined by concern: the documents, links, joints and frames (RobotModelBuilder.cpp),
        the planning and held joints and SRDF groups (PlanningJoints.cpp), the collision elements and their
        spheres (CollisionGeometry.cpp), the self-collision pairs (SelfPairs.cpp). */
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

        std::shared_ptr<const RobotModel> build(const std::string &urdfXml, const std::string &srdfXml);

    private:
        [[noreturn]] void fail(const std::string &what) const { throw Error("URDF '" + urdfName_ + "': " + what); }
        void failIf(const std::string &problem) const
        {
            if (!problem.empty())
                fail(problem);
        }

        // ---- documents, links, joints, frames (RobotModelBuilder.cpp)
        void checkBasePose() const;
        void readDocumentOrder(const std::string &urdfXml);
        /// urdfdom drops a <collision> whose numbers do not parse (and only logs it): check them here
        void checkCollisionNumbers(const std::string &link, int element, const tinyxml2::XMLElement *collision) const;
        void buildLinksAndJoints(const urdf::ModelInterface &urdf);
        /// model_->links_ in depth-first topological order from the root; returns link name -> index
        std::map<std::string, int> orderLinks(const urdf::ModelInterface &urdf);
        /// URDF joint \a i (document order) into model_->urdfJoints_[i]
        void readJoint(const urdf::ModelInterface &urdf, std::size_t i, const std::map<std::string, int> &linkIndex);
        void compileFrames();

        // ---- planning and held joints, SRDF groups (PlanningJoints.cpp)
        void choosePlanningJoints(const urdf::ModelInterface &urdf);
        /// the limits of every URDF joint (planning joints and held joints alike; 0 for fixed joints)
        void jointLimits(const urdf::ModelInterface &urdf, std::vector<double> &lower,
                         std::vector<double> &upper) const;
        /// the URDF joint named \a name, -1 if none
        int findJoint(const std::string &name) const;
        /// model_->groups_: every SRDF group that resolves (a group that does not is a warning, or with
        /// Options::strict an error)
        void resolveGroups(const std::vector<std::string> &candidates);
        /// the planning joints by name: Options::planningJoints, Options::group's, or every candidate
        std::vector<std::string> chosenJoints(const std::vector<std::string> &candidates);
        /// held joints: default 0 clamped into the limits, Options::jointState's value, or Options::heldJointValues'
        void holdJoints(const std::vector<double> &lower, const std::vector<double> &upper);
        /// holds URDF joint \a idx at \a value, clamped within Options::limitTolerance (unless strict)
        void holdJoint(int idx, double value, double lower, double upper, const std::string &what);

        // ---- collision geometry (CollisionGeometry.cpp)
        void checkPositive(double v, const std::string &what, const std::string &link, int element) const;
        void buildCollisionGeometry(const urdf::ModelInterface &urdf);
        /// the sphere cover (in the element's frame) of <collision> #\a element of \a link, its shape into \a g
        SphereCover coverElement(const urdf::Collision &c, const std::string &link, int element, CollisionGeometry &g,
                                 std::map<std::string, SphereCover> &meshCovers) const;
        /// the cover of a mesh, loaded once per path and scale (\a meshCovers: "path|scale" -> cover)
        SphereCover meshCover(const urdf::Mesh &mesh, const std::string &link, int element, CollisionGeometry &g,
                              std::map<std::string, SphereCover> &meshCovers) const;
        /// a collision link for URDF link \a li with the spheres \a linkSpheres (in the link frame)
        void addCollisionLink(std::size_t li, const std::vector<Sphere> &linkSpheres);

        // ---- self-collision pairs (SelfPairs.cpp)
        void buildSelfPairs();
        /// the key of the unordered link pair (a, b)
        static std::uint64_t pairKey(int a, int b);
        /// SRDF disable_collisions pairs into \a skipped; unknown links are a warning (an error when strict)
        void skipSrdfPairs(const std::unordered_map<std::string, int> &linkIndex,
                           std::unordered_set<std::uint64_t> &skipped);
        /** \brief The links with collision geometry adjacent to link \a from: the tree path between them has at
            most one non-fixed joint and every link strictly inside it has no collision geometry. Found by a walk
            from \a from that stops at geometry and at a second non-fixed joint, so its cost is the size of that
            neighbourhood (not the depth of the tree for every pair of links). */
        std::vector<int> adjacentLinks(int from, const std::vector<int> &collisionOf,
                                       const std::vector<std::vector<int>> &childJoints) const;
        /// true when some sphere of collision link \a a touches (distance <= sum of radii) one of link \a b
        bool inContact(const std::vector<Eigen::Vector3d> &centers, int a, int b) const;
        std::pair<std::string, std::string> pairNames(const std::pair<int, int> &p) const;
        void findAlwaysAndDefaultPairs();

        std::shared_ptr<RobotModel> model_;
        std::string urdfName_, srdfName_;
        const RobotModel::Options &options_;
        SrdfDocument srdf_;
        bool hasSrdf_{false};
        std::vector<std::string> jointOrder_;
        std::map<std::string, int> collisionCount_;
    };
}  // namespace ropras::ompl_ext

#endif
