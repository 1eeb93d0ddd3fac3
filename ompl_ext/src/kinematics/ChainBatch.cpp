// KinematicChain::tipPosesBatch: the chain's FK on 4 configurations at a time, structure of arrays in double.
// The lanes are GCC/Clang vector extensions: one 4-wide AVX2 register per value when the compiler targets AVX2
// (the library is built with -march=native), two SSE2 halves or scalar code otherwise; the same source either way.
#include <cmath>
#include <cstring>

#include "ropras/ompl_ext/kinematics/KinematicChain.h"

namespace ropras::ompl_ext
{
    namespace
    {
        constexpr std::size_t LANES = 4;
        typedef double Lanes __attribute__((vector_size(LANES * sizeof(double))));

        /// 3x3 rotation (column-major, r[3 * col + row]) and translation of 4 configurations
        struct FrameLanes
        {
            Lanes r[9];
            Lanes t[3];
        };

        /// f <- f * offset (a constant rigid transform, the same in every lane)
        inline void applyOffset(FrameLanes &f, const Eigen::Isometry3d &offset) noexcept
        {
            const Eigen::Matrix3d &o = offset.linear();
            const Eigen::Vector3d &p = offset.translation();
            for (int row = 0; row < 3; ++row)
                f.t[row] += f.r[row] * p[0] + f.r[3 + row] * p[1] + f.r[6 + row] * p[2];
            Lanes out[9];
            for (int col = 0; col < 3; ++col)
                for (int row = 0; row < 3; ++row)
                    out[3 * col + row] = f.r[row] * o(0, col) + f.r[3 + row] * o(1, col) + f.r[6 + row] * o(2, col);
            std::memcpy(f.r, out, sizeof(out));
        }

        /// 4 configurations' tip poses into out (12 doubles each); \a lanes of them are real
        void blockPoses(const std::vector<ChainJoint> &joints, const Eigen::Isometry3d &tipOffset, const double *qs,
                        std::size_t dof, std::size_t lanes, double *out) noexcept
        {
            FrameLanes f;
            for (int k = 0; k < 9; ++k)
                f.r[k] = Lanes{} + (k % 4 == 0 ? 1.0 : 0.0);
            for (Lanes &t : f.t)
                t = Lanes{};
            for (const ChainJoint &j : joints)
            {
                applyOffset(f, j.offset);
                Lanes v;
                for (std::size_t l = 0; l < LANES; ++l)
                    v[l] = qs[std::min(l, lanes - 1) * dof + static_cast<std::size_t>(j.variable)];
                if (j.prismatic)
                {
                    for (int row = 0; row < 3; ++row)
                        f.t[row] += f.r[6 + row] * v;
                    continue;
                }
                Lanes c, s;
                for (std::size_t l = 0; l < LANES; ++l)
                {
                    c[l] = std::cos(v[l]);
                    s[l] = std::sin(v[l]);
                }
                for (int row = 0; row < 3; ++row)
                {
                    const Lanes c0 = f.r[row], c1 = f.r[3 + row];
                    f.r[row] = c * c0 + s * c1;
                    f.r[3 + row] = c * c1 - s * c0;
                }
            }
            applyOffset(f, tipOffset);
            for (std::size_t l = 0; l < lanes; ++l)
            {
                double *o = out + 12 * l;
                for (int k = 0; k < 9; ++k)
                    o[k] = f.r[k][l];
                for (int k = 0; k < 3; ++k)
                    o[9 + k] = f.t[k][l];
            }
        }
    }  // namespace

    void KinematicChain::tipPosesBatch(const double *qs, std::size_t count, double *out) const noexcept
    {
        const std::size_t dof = robot_->dof();
        for (std::size_t k = 0; k < count; k += LANES)
        {
            const std::size_t lanes = std::min(LANES, count - k);
            blockPoses(joints_, tipOffset_, qs + k * dof, dof, lanes, out + 12 * k);
        }
    }
}  // namespace ropras::ompl_ext
