// The compact float "kinematic program" a CollisionChecker compiles a RobotModel into.
#ifndef ROPRAS_OMPL_EXT_SIMD_KINEMATIC_PROGRAM_H
#define ROPRAS_OMPL_EXT_SIMD_KINEMATIC_PROGRAM_H

#include <cstddef>
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
        /// the same offset as three rows (r0 r1 r2 t) for the single-configuration path
        alignas(16) float offsetRows[12];
        /// the offset rotation is a signed permutation (rpy in multiples of pi/2, common in URDFs): column j of
        /// T_parent * offset is sign[j] * column perm[j] of T_parent, no multiplications
        bool permutation{false};
        int perm[3]{0, 1, 2};
        float sign[3]{1, 1, 1};
        /// offset translation components that are non-zero (bit k)
        unsigned translationMask{7};
    };

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
    };

    /** \brief Offsets (in floats) into the per-thread scratch buffer. */
    struct ScratchLayout
    {
        std::size_t frames{0}, sin{0}, cos{0}, q{0}, sx{0}, sy{0}, sz{0}, lx{0}, ly{0}, lz{0}, total{0};
    };

    struct KinematicProgram
    {
        int dof{0};
        std::vector<FrameOp> frames;
        std::vector<LinkOp> links;
        /// sphere positions in their frames and radii, in program order (link blocks padded, see LinkOp)
        std::vector<float> sx, sy, sz, sr;
        int sphereSlots{0};  ///< total padded length
        /// program index of each RobotModel sphere
        std::vector<int> programIndexOfSphere;
        /// link bound radii padded to a multiple of WIDTH with 0
        std::vector<float> linkRadius;
        int linkPadded{0};
        std::vector<std::pair<int, int>> selfPairs;  ///< indices into links
        /// per self pair: float (a.br + b.br)^2 and the batch offsets WIDTH * link of both links
        std::vector<float> selfPairReach2;
        std::vector<int> selfPairOffsetA, selfPairOffsetB;
        std::vector<double> lower, upper;  ///< per variable
        std::vector<char> unbounded;       ///< continuous joints: any finite value
        std::vector<char> rotational;      ///< variable drives a RotateZ frame
        ScratchLayout single, batch;
    };
}  // namespace ropras::ompl_ext::simd

#endif
