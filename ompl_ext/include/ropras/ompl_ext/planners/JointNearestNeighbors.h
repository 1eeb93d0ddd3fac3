#ifndef ROPRAS_OMPL_EXT_JOINT_NEAREST_NEIGHBORS_H
#define ROPRAS_OMPL_EXT_JOINT_NEAREST_NEIGHBORS_H

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/datastructures/NearestNeighbors.h>
#include <ompl/util/Exception.h>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace ropras::ompl_ext
{
    /** \brief Exact nearest neighbours of a planner's tree nodes in a RealVectorStateSpace with the Euclidean
        distance (JointStateSpace): an ompl::NearestNeighbors<T> for any T that points to a record with a
        `state` member (OMPL's planners' Motion), e.g. OMPL's RRTConnect through PlannerRegistry.

        OMPL's default for a metric space is GNAT, whose every query calls the distance function through
        std::function for a few hundred nodes of a tree of thousands and walks its pivots; in a 7- to 14-joint
        space that query is the largest cost of RRTConnect on hard problems (cage: about a third of the solve).
        This structure keeps a copy of the nodes' values in blocks of four nodes ([block][joint][lane], doubles)
        and answers nearest() by one linear scan of squared differences, four nodes per vector step, with no call
        per node. The answer is the node with the least squared Euclidean distance (the first added among exact
        ties), i.e. the node GNAT returns, up to the rounding of the last bit (a different summation order).
        nearestK and nearestR use the distance function as OMPL's NearestNeighborsLinear does.

        The values of an element's state must not change while it is in the structure (true for the trees of
        OMPL's planners). Not thread-safe for concurrent add and query (as GNATNoThreadSafety). */
    template <typename T>
    class JointNearestNeighbors : public ompl::NearestNeighbors<T>
    {
    public:
        /// \a dof: the state space's dimension (every element's state has that many values)
        explicit JointNearestNeighbors(std::size_t dof) : dof_(dof) {}

        bool reportsSortedResults() const override { return true; }

        void clear() override
        {
            data_.clear();
            values_.clear();
        }

        void add(const T &element) override
        {
            if (data_.size() % LANES == 0)
                values_.insert(values_.end(), LANES * dof_, FAR);
            const std::size_t n = data_.size();
            const double *q = valuesOf(element);
            double *block = values_.data() + (n / LANES) * LANES * dof_;
            for (std::size_t k = 0; k < dof_; ++k)
                block[k * LANES + n % LANES] = q[k];
            data_.push_back(element);
        }

        bool remove(const T &element) override
        {
            const auto it = std::find(data_.begin(), data_.end(), element);
            if (it == data_.end())
                return false;
            // keep the insertion order (ties go to the first added): rebuild the blocks from the removed one on
            const std::size_t from = static_cast<std::size_t>(it - data_.begin());
            std::vector<T> tail(it + 1, data_.end());
            data_.resize(from);
            values_.resize((from + LANES - 1) / LANES * LANES * dof_);
            if (from % LANES != 0)  // the removed element's block keeps its first lanes
            {
                double *block = values_.data() + (from / LANES) * LANES * dof_;
                for (std::size_t k = 0; k < dof_; ++k)
                    for (std::size_t l = from % LANES; l < LANES; ++l)
                        block[k * LANES + l] = FAR;
            }
            for (const T &e : tail)
                add(e);
            return true;
        }

        T nearest(const T &element) const override
        {
            if (data_.empty())
                throw ompl::Exception("No elements found in nearest neighbors data structure");
            return data_[nearestIndex(valuesOf(element))];
        }

        void nearestK(const T &element, std::size_t k, std::vector<T> &nbh) const override
        {
            nbh = data_;
            if (nbh.size() > k)
            {
                std::partial_sort(nbh.begin(), nbh.begin() + static_cast<std::ptrdiff_t>(k), nbh.end(),
                                  ElementSort(element, this->distFun_));
                nbh.resize(k);
            }
            else
                std::sort(nbh.begin(), nbh.end(), ElementSort(element, this->distFun_));
        }

        void nearestR(const T &element, double radius, std::vector<T> &nbh) const override
        {
            nbh.clear();
            for (const T &e : data_)
                if (this->distFun_(e, element) <= radius)
                    nbh.push_back(e);
            std::sort(nbh.begin(), nbh.end(), ElementSort(element, this->distFun_));
        }

        std::size_t size() const override { return data_.size(); }

        void list(std::vector<T> &data) const override { data = data_; }

        /// index (in the order of add()) of the element nearest to the values \a q; size() > 0. A NaN query gives 0.
        std::size_t nearestIndex(const double *q) const noexcept
        {
            using Double4 = double __attribute__((vector_size(LANES * sizeof(double))));
            using Index4 = std::int64_t __attribute__((vector_size(LANES * sizeof(std::int64_t))));
            static_assert(LANES == 4, "one 4-double vector per joint and block");
            const std::size_t blocks = (data_.size() + LANES - 1) / LANES;
            const double inf = std::numeric_limits<double>::infinity();
            Double4 best = {inf, inf, inf, inf};
            Index4 bestIndex = {0, 1, 2, 3}, index = bestIndex;
            const Index4 step = {4, 4, 4, 4};
            const double *block = values_.data();
            for (std::size_t b = 0; b < blocks; ++b, block += LANES * dof_)
            {
                Double4 d = {0.0, 0.0, 0.0, 0.0};
                for (std::size_t k = 0; k < dof_; ++k)
                {
                    Double4 v;
                    std::memcpy(&v, block + k * LANES, sizeof v);
                    const Double4 e = v - q[k];
                    d += e * e;
                }
                const Index4 better = d < best;  // strictly: a lane keeps its first node among ties
                best = better ? d : best;
                bestIndex = better ? index : bestIndex;
                index += step;
            }
            std::size_t result = static_cast<std::size_t>(bestIndex[0]);
            double bestD = best[0];
            for (std::size_t l = 1; l < LANES; ++l)
                if (best[l] < bestD || (best[l] == bestD && static_cast<std::size_t>(bestIndex[l]) < result))
                {
                    bestD = best[l];
                    result = static_cast<std::size_t>(bestIndex[l]);
                }
            return result;
        }

    private:
        static constexpr std::size_t LANES = 4;
        /// the value of unused lanes: its squared difference is infinite, so such a lane never wins
        static constexpr double FAR = std::numeric_limits<double>::infinity();

        static const double *valuesOf(const T &element)
        {
            return element->state->template as<ompl::base::RealVectorStateSpace::StateType>()->values;
        }

        struct ElementSort
        {
            ElementSort(const T &e, const typename ompl::NearestNeighbors<T>::DistanceFunction &df)
                : element(e), distFun(df)
            {
            }
            bool operator()(const T &a, const T &b) const { return distFun(a, element) < distFun(b, element); }
            const T &element;
            const typename ompl::NearestNeighbors<T>::DistanceFunction &distFun;
        };

        std::size_t dof_;
        std::vector<T> data_;
        std::vector<double> values_;
    };
}  // namespace ropras::ompl_ext

#endif
