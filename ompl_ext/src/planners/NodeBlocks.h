#ifndef ROPRAS_OMPL_EXT_NODE_BLOCKS_H
#define ROPRAS_OMPL_EXT_NODE_BLOCKS_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>
#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

namespace ropras::ompl_ext
{
    /** \brief A float copy of a tree's node configurations for nearest-neighbour scans (private to
        VectorizedRRTConnect): blocks of LANES nodes, stored [block][joint][lane], so that one SIMD register
        holds one joint of LANES nodes. Unused lanes of the last block lie far away and never win.

        nearest() is a linear scan (trees stay small at the median MotionBenchMaker problem): squared
        distances in float, each lane keeps its best node (the earliest on ties), then the lanes are reduced
        (smallest distance, then smallest index), so the result is the same with and without AVX2. Ties
        within float rounding may pick a different node than a double scan would. */
    class NodeBlocks
    {
    public:
        static constexpr std::size_t LANES = 8;
        static constexpr std::size_t MAX_DOF = 64;

        /// empties and sets the number of joints (at most MAX_DOF; the caller checks)
        void reset(std::size_t dof)
        {
            dof_ = dof;
            clear();
        }
        /// forgets the nodes, keeps the capacity
        void clear()
        {
            values_.clear();
            size_ = 0;
        }
        void reserve(std::size_t nodes) { values_.reserve((nodes + LANES - 1) / LANES * LANES * dof_); }
        std::size_t size() const { return size_; }

        void add(const double *q)
        {
            if (size_ % LANES == 0)
                values_.insert(values_.end(), LANES * dof_, FAR);
            float *block = values_.data() + (size_ / LANES) * LANES * dof_;
            for (std::size_t k = 0; k < dof_; ++k)
                block[k * LANES + size_ % LANES] = static_cast<float>(q[k]);
            ++size_;
        }

        /// index of the node nearest to \a q (size() > 0); a NaN query gives node 0
        std::size_t nearest(const double *q) const noexcept
        {
            float qf[MAX_DOF];
            for (std::size_t k = 0; k < dof_; ++k)
                qf[k] = static_cast<float>(q[k]);
            return nearest(qf);
        }

        /// the same for a query already in float (the planner converts its samples once, while drawing them);
        /// \a distSq, when non-null, receives the float squared distance to the node returned
        std::size_t nearest(const float *qf, float *distSq = nullptr) const noexcept
        {
            const std::size_t blocks = (size_ + LANES - 1) / LANES;
            const float *block = values_.data();
#if defined(__AVX2__) && defined(__FMA__)
            static_assert(LANES == 8, "one AVX2 register per joint and block");
            __m256 bestDv = _mm256_set1_ps(std::numeric_limits<float>::infinity());
            __m256i bestIv = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
            __m256i index = bestIv;
            const __m256i step = _mm256_set1_epi32(static_cast<int>(LANES));
            for (std::size_t b = 0; b < blocks; ++b, block += LANES * dof_)
            {
                __m256 d = _mm256_setzero_ps();
                for (std::size_t k = 0; k < dof_; ++k)
                {
                    const __m256 e = _mm256_sub_ps(_mm256_loadu_ps(block + k * LANES), _mm256_set1_ps(qf[k]));
                    d = _mm256_fmadd_ps(e, e, d);
                }
                const __m256 better = _mm256_cmp_ps(d, bestDv, _CMP_LT_OQ);
                bestDv = _mm256_blendv_ps(bestDv, d, better);
                bestIv = _mm256_castps_si256(
                    _mm256_blendv_ps(_mm256_castsi256_ps(bestIv), _mm256_castsi256_ps(index), better));
                index = _mm256_add_epi32(index, step);
            }
            // Reduce in registers: the smallest distance, then among the lanes holding it the smallest index
            // (one lane almost always; a loop over the tied lanes otherwise).
            __m256 m = _mm256_min_ps(bestDv, _mm256_permute_ps(bestDv, 0xb1));  // swap neighbours
            m = _mm256_min_ps(m, _mm256_permute_ps(m, 0x4e));                   // swap pairs
            m = _mm256_min_ps(m, _mm256_permute2f128_ps(m, m, 0x01));           // swap halves
            unsigned tied = static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(bestDv, m, _CMP_EQ_OQ)));
            alignas(32) std::int32_t bestI[LANES];
            _mm256_store_si256(reinterpret_cast<__m256i *>(bestI), bestIv);
            if (tied == 0u)  // NaN query: no lane ever improved on infinity (all equal) or NaN compares unequal
                tied = 1u;
            std::size_t best = static_cast<std::size_t>(bestI[__builtin_ctz(tied)]);
            for (tied &= tied - 1u; tied != 0u; tied &= tied - 1u)
                best = std::min(best, static_cast<std::size_t>(bestI[__builtin_ctz(tied)]));
            const float bestDist = _mm_cvtss_f32(_mm256_castps256_ps128(m));
#else
            float bestD[LANES];
            std::int32_t bestI[LANES];
            for (std::size_t l = 0; l < LANES; ++l)
            {
                bestD[l] = std::numeric_limits<float>::infinity();
                bestI[l] = static_cast<std::int32_t>(l);
            }
            for (std::size_t b = 0; b < blocks; ++b, block += LANES * dof_)
                for (std::size_t l = 0; l < LANES; ++l)
                {
                    float d = 0.0f;
                    for (std::size_t k = 0; k < dof_; ++k)
                    {
                        const float e = block[k * LANES + l] - qf[k];
                        d = e * e + d;
                    }
                    if (d < bestD[l])
                    {
                        bestD[l] = d;
                        bestI[l] = static_cast<std::int32_t>(b * LANES + l);
                    }
                }
            std::size_t best = static_cast<std::size_t>(bestI[0]);
            float bestDist = bestD[0];
            for (std::size_t l = 1; l < LANES; ++l)
                if (bestD[l] < bestDist || (bestD[l] == bestDist && static_cast<std::size_t>(bestI[l]) < best))
                {
                    bestDist = bestD[l];
                    best = static_cast<std::size_t>(bestI[l]);
                }
#endif
            if (distSq != nullptr)
                *distSq = bestDist;
            return best < size_ ? best : 0;  // only a NaN query leaves a lane index past the end
        }

    private:
        static constexpr float FAR = 1.0e18f;  ///< squared: 1e36, summed over MAX_DOF joints still finite
        std::vector<float> values_;
        std::size_t dof_{0};
        std::size_t size_{0};
    };
}  // namespace ropras::ompl_ext

#endif
