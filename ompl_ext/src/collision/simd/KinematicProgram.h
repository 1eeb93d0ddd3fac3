// The compact float "kinematic program" a CollisionChecker compiles a RobotModel into.
#ifndef ROPRAS_OMPL_EXT_SIMD_KINEMATIC_PROGRAM_H
#define ROPRAS_OMPL_EXT_SIMD_KINEMATIC_PROGRAM_H

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace ropras::ompl_ext::simd
{
    /// lanes per batch, for every backend
    constexpr int WIDTH = 8;

    /// how a frame moves with its variable
    enum class Motion : int
    {
        None = 0,
        RotateZ = 1,
        TranslateZ = 2
    };

    /** \brief One frame: T = T_parent * offset * Motion(q[variable]). Transforms are 12 floats: the rotation
        row-major (r00 r01 r02 r10 ... r22), then the translation (tx ty tz). */
    struct FrameOp
    {
        int parent{-1};
        int variable{-1};
        Motion motion{Motion::None};
        float offset[12];
        /** \brief The offset for the single path's two-column products (8 floats each, two halves of 4 equal
            values): for k = 0, 1, 2, pairs k = (o_k0 | o_k1) and pairs 3 + k = (o_k2 | t_k), so that the columns
            (c0 | c1) of T_parent * offset are sum_k (c_k | c_k) * pairs[k], and (c2 | t) are
            sum_k (c_k | c_k) * pairs[3 + k] + (0 | t). */
        alignas(32) float offsetPairs[48];
        /// the offset rotation is a signed permutation (rpy in multiples of pi/2, common in URDFs): column j of
        /// T_parent * offset is +- column PERMUTATIONS[permId][j] of T_parent, no multiplications
        bool permutation{false};
        /// offset translation components that are non-zero (bit k)
        unsigned translationMask{7};
        /// pre-decoded permutation for the batch path: index into PERMUTATIONS, and the columns j whose sign is
        /// negative (bit j), flipped with an XOR of the sign bit (no multiplication)
        int permId{0};
        unsigned flipColumns{0};
        /// the links carried by this frame: KinematicProgram::frameLinks[linkBegin, linkEnd)
        int linkBegin{0}, linkEnd{0};
    };

    /// the six permutations of three columns; FrameOp::permId indexes this table
    constexpr int PERMUTATIONS[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

    /** \brief A collision link: its frame, bounding sphere (frame coordinates) and spheres [first, first+count)
        in the program's sphere order. Each link's block starts at a multiple of WIDTH and is padded to
        \a padded (a multiple of WIDTH) with copies of its own spheres, so whole-chunk tests need no masks. */
    struct LinkOp
    {
        int frame{0};
        float bx{0}, by{0}, bz{0}, br{0};
        int first{0};
        int count{0};
        int padded{0};
        int collisionLink{-1};  ///< RobotModel::collisionLinks() index it belongs to
    };

    /// most link groups a program has (LinkGroup)
    constexpr int MAX_LINK_GROUPS = 16;

    /** \brief Consecutive program links [begin, end) whose per-lane bounding box the batch path tests first:
        an obstacle (or another group) that misses the box misses every link of the group in that lane. */
    struct LinkGroup
    {
        int begin{0}, end{0};
    };

    /** \brief Self pairs [begin, end) (KinematicProgram::selfPairs, sorted by group pair) whose first links are in
        group groupA and second links in groupB. */
    struct SelfPairRange
    {
        int groupA{0}, groupB{0}, begin{0}, end{0};
        /// its rows: KinematicProgram::selfPairRows[rowBegin, rowEnd)
        int rowBegin{0}, rowEnd{0};
    };

    /** \brief Self pairs pairBegin + i (i < count <= WIDTH) = (a, bFirst + i): one link against consecutive links,
        tested as one vector in the single-configuration path. */
    struct SelfPairRow
    {
        int a{0}, bFirst{0}, count{0}, pairBegin{0};
    };

    /** \brief Offsets (in floats) into the per-thread scratch buffer. */
    struct ScratchLayout
    {
        std::size_t frames{0}, sin{0}, cos{0}, q{0}, sx{0}, sy{0}, sz{0}, lx{0}, ly{0}, lz{0}, total{0};
    };

    /** \brief SpherePairFreeCells in float for the batch path: the cell of lane values v0 (and v1) is
        clamp(int((v - lower) * inv), 0, cells - 1); its bit in KinematicProgram::selfGridBits from bitsOffset. */
    struct SelfGrid
    {
        int var[2]{-1, -1};  ///< var[1] = -1: a grid over one variable
        float lower[2]{0.0f, 0.0f}, inv[2]{0.0f, 0.0f};
        int cells{0};
        int bitsOffset{0};
    };

    /// grids a batch consults (the others are ignored: a grid only ever removes work)
    constexpr int MAX_SELF_GRIDS = 32;

    struct KinematicProgram
    {
        /// the RobotModel compiled (attached bodies name their model; another model's are not ours to place)
        const void *model{nullptr};
        int dof{0};
        std::vector<FrameOp> frames;
        std::vector<LinkOp> links;
        /// link indices grouped by frame (see FrameOp::linkBegin)
        std::vector<int> frameLinks;
        /// sphere positions in their frames and radii, in program order (link blocks padded, see LinkOp)
        std::vector<float> sx, sy, sz, sr;
        int sphereSlots{0};  ///< total padded length
        /// program index of each RobotModel sphere
        std::vector<int> programIndexOfSphere;
        /// RobotModel sphere of each program slot, -1 in the padding
        std::vector<int> sphereOfSlot;
        /// link bound radii padded to a multiple of WIDTH with 0
        std::vector<float> linkRadius;
        /// link frames (FrameOp index, exact in float) padded like linkRadius with -1: one vector compare finds the
        /// links a frame carries
        std::vector<float> linkFrame;
        /// per link 16 floats (bx x4 | by x4 | bz x4 | 1 x4): its bound centre for the single path's two-column product
        std::vector<float> linkBoundPairs;
        int linkPadded{0};
        /// link groups (at most MAX_LINK_GROUPS, covering every link in order)
        std::vector<LinkGroup> groups;
        std::vector<int> groupOfLink;                ///< per link: its group
        std::vector<std::pair<int, int>> selfPairs;  ///< indices into links, sorted by the groups of both
        std::vector<SelfPairRange> selfPairRanges;
        std::vector<SelfPairRow> selfPairRows;
        /// per row WIDTH floats: (r_a + r_b)^2 of its pairs, -1 in the lanes past count (never reached)
        std::vector<float> selfRowReach2;
        /// per self pair: float (a.br + b.br)^2 and the batch offsets WIDTH * link of both links
        std::vector<float> selfPairReach2;
        std::vector<int> selfPairOffsetA, selfPairOffsetB;
        /// per self pair WIDTH masks: bit j of mask i set when sphere slot first + i of link A can touch slot
        /// first + j of link B within the joint limits (reachableSpherePairs); the other sphere pairs never touch
        std::vector<std::uint8_t> selfPairSphereMasks;
        /// per self pair: the slots of link A with a non-empty mask (bit i)
        std::vector<std::uint8_t> selfPairSlotsA;
        /** \brief Per self pair, 8 floats: a sphere (x y z r, in A's frame) around the spheres of A that can touch
            B, and one (in B's frame) around the spheres of B that A can touch; float (rA + rB)^2 in selfPairNearReach2.
            When the pair's link bounds touch, the batch path tests these first (selfPairUseNear). */
        std::vector<float> selfPairNear, selfPairNearReach2;
        std::vector<char> selfPairUseNear;
        /// per self pair: its grid of free cells in selfGrids, or -1
        std::vector<int> selfPairGrid;
        std::vector<SelfGrid> selfGrids;
        std::vector<std::uint32_t> selfGridBits;
        /// per variable: v is valid iff lowerCheck <= v <= upperCheck (finite bounds; +-DBL_MAX when unbounded)
        std::vector<double> lowerCheck, upperCheck;
        std::vector<char> rotational;  ///< variable drives a RotateZ frame
        /// rotational variables whose limits reach past +-64 (an angle the batch loader may have to reduce)
        std::vector<int> reduceCheck;
        ScratchLayout single, batch;

        /// bit \a cell of grid \a g: the cell is free
        bool cellFree(const SelfGrid &g, std::uint32_t cell) const noexcept
        {
            return ((selfGridBits[static_cast<std::size_t>(g.bitsOffset) + (cell >> 5)] >> (cell & 31u)) & 1u) != 0u;
        }
    };
}  // namespace ropras::ompl_ext::simd

#endif
