#ifndef ROPRAS_OMPL_EXT_SPHERE_REACH_H
#define ROPRAS_OMPL_EXT_SPHERE_REACH_H

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace ropras::ompl_ext
{
    class RobotModel;

    /** \brief Limits of reachableSpherePairs. */
    struct SphereReachOptions
    {
        /// a sphere pair is kept when it can come within this distance (m) of contact
        double margin{5e-4};
        /// joints between the two links beyond which the pair is not analysed (every sphere pair kept)
        int maxVariables{2};
        /// joint-space boxes evaluated per link pair; the pairs still undecided then are kept
        int boxBudget{3000};
        /// cells per joint of SphereReach::freeCells (0: no grid)
        int freeCellsPerJoint{128};
    };

    /** \brief A grid over the one or two revolute joints between two links: the cells in which none of their
        reachable sphere pairs can come within the margin of contact. A checker that finds a configuration in a
        free cell skips the link pair. */
    struct SpherePairFreeCells
    {
        /// planning-variable indices of the grid's joints (1 or 2); empty: no grid
        std::vector<int> variables;
        /// per variable: where the grid starts (its lower limit) and the cell width
        std::vector<double> lower, width;
        /// cells per variable
        int cells{0};
        /// bit i0 * cells + i1 (i1 = 0 with one variable) set: the cell is free
        std::vector<std::uint32_t> bits;
        /// free cells over all cells
        double freeFraction() const noexcept;
        /// true when \a q (every planning value) lies in a free cell; false without a grid
        bool isFree(const double *q) const noexcept;
    };

    /** \brief What reachableSpherePairs found for one pair of collision links. */
    struct SphereReach
    {
        /// (sphere of link A, sphere of link B), RobotModel::spheres() indices, that may come within the margin
        std::vector<std::pair<int, int>> pairs;
        /// false when the links were not analysed (a prismatic joint or more than maxVariables joints between
        /// them): then every sphere pair is listed
        bool analysed{false};
        /// joint-space boxes evaluated
        std::size_t boxes{0};
        /// true when the box budget ran out (the undecided pairs were kept)
        bool budgetExhausted{false};
        /** \brief Where \a pairs cannot touch, when the links are analysed, \a pairs is not empty and every joint
            between them is revolute with finite limits. Each cell is evaluated like a box of the search below,
            widened by 1e-5 rad on each side (so that a float rounding of the joint values cannot leave its cell). */
        SpherePairFreeCells freeCells;
    };

    /** \brief The sphere pairs of two collision links (RobotModel::collisionLinks() indices) that can touch for
        some configuration within the joint limits; the others can never collide and need no test.

        The joints on the kinematic path between the two links span a box of joint values. Branch and bound over
        that box: at a box's centre the exact (double) sphere distances are computed in the frame of the links'
        common ancestor; a change of joint j by d moves a point by at most |d| times its distance from j's axis,
        which is bounded (for every value of the other joints) by the xy length of the first offset below j plus
        the lengths of the further offsets down to the point's frame and of the sphere's offset in that frame. So over a
       box with half widths h, a pair's distance is at least the centre distance minus sum_j L_j h_j. A pair is dropped
       from a box when that bound exceeds the radii plus the margin, kept as soon as some evaluated configuration brings
       it within the margin, and the box is halved along its widest (Lipschitz-weighted) joint otherwise. Pairs still
       undecided when the box budget runs out are kept, and links with a prismatic joint or more than maxVariables
       joints between them keep every pair: the result never omits a pair that can touch. Continuous joints range over
       [-pi, pi]. Throws Error for link indices out of range or invalid options. */
    SphereReach reachableSpherePairs(const RobotModel &model, int linkA, int linkB,
                                     const SphereReachOptions &options = SphereReachOptions());
}  // namespace ropras::ompl_ext

#endif
