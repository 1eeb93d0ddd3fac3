#include "ropras/ompl_ext/scene/ObstacleIndex.h"

#include <algorithm>
#include <iterator>
#include <limits>

#include "ropras/ompl_ext/scene/Environment.h"

namespace ropras::ompl_ext
{
    namespace
    {
        constexpr std::size_t FANOUT = OBSTACLE_INDEX_FANOUT;

        /// nodes of a tree over \a n primitives: ceil(n / 8) leaves, then ceil(level / 8) per level up to one root
        std::size_t nodeCount(std::size_t n)
        {
            std::size_t total = 0, level = (n + FANOUT - 1) / FANOUT;
            for (;;)
            {
                total += level;
                if (level <= 1)
                    return total;
                level = (level + FANOUT - 1) / FANOUT;
            }
        }

        template <class T>
        void reserveGrowing(std::vector<T> &v, std::size_t n)
        {
            if (v.capacity() < n)
                v.reserve(std::max(n, 2 * v.capacity()));
        }

        ObstacleIndexNode emptyNode()
        {
            ObstacleIndexNode node{};
            constexpr float inf = std::numeric_limits<float>::infinity();
            for (float *lo : {node.lox, node.loy, node.loz})
                std::fill(lo, lo + FANOUT, inf);
            for (float *hi : {node.hix, node.hiy, node.hiz})
                std::fill(hi, hi + FANOUT, -inf);
            std::fill(std::begin(node.child), std::end(node.child), -1);
            return node;
        }

        void setLane(ObstacleIndexNode &node, std::size_t lane, const ObstacleAabb &b)
        {
            // the same float expressions as the kernels' box tests (c - e, c + e)
            node.lox[lane] = b.cx - b.ex;
            node.loy[lane] = b.cy - b.ey;
            node.loz[lane] = b.cz - b.ez;
            node.hix[lane] = b.cx + b.ex;
            node.hiy[lane] = b.cy + b.ey;
            node.hiz[lane] = b.cz + b.ez;
        }

        /// the box around node \a from's lanes into lane \a lane of \a to (min and max are exact: no rounding)
        void setUnion(const ObstacleIndexNode &from, ObstacleIndexNode &to, std::size_t lane)
        {
            to.lox[lane] = *std::min_element(from.lox, from.lox + FANOUT);
            to.loy[lane] = *std::min_element(from.loy, from.loy + FANOUT);
            to.loz[lane] = *std::min_element(from.loz, from.loz + FANOUT);
            to.hix[lane] = *std::max_element(from.hix, from.hix + FANOUT);
            to.hiy[lane] = *std::max_element(from.hiy, from.hiy + FANOUT);
            to.hiz[lane] = *std::max_element(from.hiz, from.hiz + FANOUT);
        }

        /** \brief Orders primitives [begin, end) of \a order (primitive in the low 32 bits) so that every aligned
            block of 8^k entries is a compact group: the range is cut at the median of its centres along their
            longest extent, recursively, at multiples of the full subtrees' size (so the leaves, eight consecutive
            entries, and every level above are groups of a top-down median split; no allocation). */
        struct MedianOrder
        {
            const Environment &env;
            std::uint64_t *order;

            float centre(std::uint64_t entry, int axis) const
            {
                const ObstacleAabb &b = env.primitiveBox(static_cast<std::size_t>(entry & 0xffffffffu));
                return axis == 0 ? b.cx : axis == 1 ? b.cy : b.cz;
            }

            void node(std::size_t begin, std::size_t end) const
            {
                if (end - begin <= FANOUT)
                    return;
                std::size_t child = FANOUT;  // capacity of a child subtree: the largest power of 8 below the size
                while (child * FANOUT < end - begin)
                    child *= FANOUT;
                split(begin, end, (end - begin + child - 1) / child, child);
            }

            /// [begin, end) into \a groups groups of \a size (the last one smaller), each then a node
            void split(std::size_t begin, std::size_t end, std::size_t groups, std::size_t size) const
            {
                if (groups <= 1)
                {
                    node(begin, end);
                    return;
                }
                float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                               std::numeric_limits<float>::infinity()};
                float hi[3] = {-lo[0], -lo[1], -lo[2]};
                for (std::size_t k = begin; k < end; ++k)
                    for (int i = 0; i < 3; ++i)
                    {
                        lo[i] = std::min(lo[i], centre(order[k], i));
                        hi[i] = std::max(hi[i], centre(order[k], i));
                    }
                int axis = 0;
                for (int i = 1; i < 3; ++i)
                    if (hi[i] - lo[i] > hi[axis] - lo[axis])
                        axis = i;
                const std::size_t left = groups / 2, mid = begin + left * size;
                std::nth_element(order + begin, order + mid, order + end,
                                 [&](std::uint64_t x, std::uint64_t y)
                                 {
                                     const float cx = centre(x, axis), cy = centre(y, axis);
                                     return cx < cy || (cx == cy && x < y);
                                 });
                split(begin, mid, left, size);
                split(mid, end, groups - left, size);
            }
        };
    }  // namespace

    void ObstacleIndex::added(std::size_t primitives)
    {
        if (primitives < MIN_PRIMITIVES)
            return;
        if (!state_ || state_.use_count() != 1)
        {
            // a new tree: the one shared with copies stays theirs (it is rebuilt anyway, so nothing is copied)
            auto fresh = std::make_shared<State>();
            if (state_)
            {
                const std::lock_guard<std::mutex> lock(state_->mutex);  // a copy may be building it
                fresh->tree.nodes.reserve(state_->tree.nodes.capacity());
            }
            state_ = std::move(fresh);
        }
        else
            std::atomic_thread_fence(std::memory_order_acquire);  // copies destroyed elsewhere are done with it
        State &s = *state_;
        s.fresh.store(false, std::memory_order_relaxed);
        // the build writes into this memory: a check never allocates
        ObstacleTree &t = s.tree;
        reserveGrowing(t.nodes, nodeCount(primitives));
        reserveGrowing(t.parent, nodeCount(primitives));
        reserveGrowing(t.slot, primitives);
        reserveGrowing(t.sortKeys, primitives);
    }

    ObstacleIndex::State &ObstacleIndex::own()
    {
        if (state_.use_count() != 1)
        {
            auto copy = std::make_shared<State>();
            {
                const std::lock_guard<std::mutex> lock(state_->mutex);  // a copy may be building it
                copy->tree = state_->tree;
                copy->refits = state_->refits;
                copy->fresh.store(state_->fresh.load(std::memory_order_relaxed), std::memory_order_relaxed);
            }
            state_ = std::move(copy);
        }
        else
            std::atomic_thread_fence(std::memory_order_acquire);
        return *state_;
    }

    void ObstacleIndex::moved(std::size_t primitive, const ObstacleAabb &box)
    {
        if (!state_)
            return;
        State &s = own();
        if (!s.fresh.load(std::memory_order_relaxed))
            return;  // the build reads the new box
        ObstacleTree &t = s.tree;
        if (++s.refits > REFITS_PER_PRIMITIVE * t.slot.size())
        {
            s.fresh.store(false, std::memory_order_relaxed);  // rebuilt by the next check
            return;
        }
        const auto slot = static_cast<std::size_t>(t.slot[primitive]);
        setLane(t.nodes[slot / FANOUT], slot % FANOUT, box);
        for (std::int32_t node = static_cast<std::int32_t>(slot / FANOUT);
             t.parent[static_cast<std::size_t>(node)] >= 0;)
        {
            const auto up = static_cast<std::size_t>(t.parent[static_cast<std::size_t>(node)]);
            setUnion(t.nodes[static_cast<std::size_t>(node)], t.nodes[up / FANOUT], up % FANOUT);
            node = static_cast<std::int32_t>(up / FANOUT);
        }
    }

    const ObstacleTree *ObstacleIndex::buildTree(const Environment &env) const noexcept
    {
        State &s = *state_;
        const std::lock_guard<std::mutex> lock(s.mutex);
        if (!s.fresh.load(std::memory_order_relaxed))
        {
            build(env, s.tree);
            s.refits = 0;
            s.fresh.store(true, std::memory_order_release);
        }
        return &s.tree;
    }

    void ObstacleIndex::build(const Environment &env, ObstacleTree &t) noexcept
    {
        // resize() stays within the capacity added() reserved: no allocation here
        const std::size_t n = env.primitiveCount();
        t.sortKeys.resize(n);
        for (std::size_t k = 0; k < n; ++k)
            t.sortKeys[k] = static_cast<std::uint64_t>(k);
        MedianOrder{env, t.sortKeys.data()}.node(0, n);

        t.leafCount = (n + FANOUT - 1) / FANOUT;
        t.nodes.resize(nodeCount(n));
        t.parent.resize(t.nodes.size());
        t.slot.resize(n);
        const ObstacleIndexNode empty = emptyNode();
        for (std::size_t leaf = 0; leaf < t.leafCount; ++leaf)
        {
            ObstacleIndexNode &node = t.nodes[leaf];
            node = empty;
            for (std::size_t lane = 0; lane < FANOUT && FANOUT * leaf + lane < n; ++lane)
            {
                const auto k = static_cast<std::size_t>(t.sortKeys[FANOUT * leaf + lane] & 0xffffffffu);
                setLane(node, lane, env.primitiveBox(k));
                node.child[lane] = static_cast<std::int32_t>(k);
                t.slot[k] = static_cast<std::int32_t>(FANOUT * leaf + lane);
            }
        }
        // levels above: node j of a level holds nodes 8j .. 8j + 7 of the level below
        std::size_t below = 0, belowCount = t.leafCount, next = t.leafCount;
        while (belowCount > 1)
        {
            const std::size_t count = (belowCount + FANOUT - 1) / FANOUT;
            for (std::size_t j = 0; j < count; ++j)
            {
                ObstacleIndexNode &node = t.nodes[next + j];
                node = empty;
                for (std::size_t lane = 0; lane < FANOUT && FANOUT * j + lane < belowCount; ++lane)
                {
                    const std::size_t child = below + FANOUT * j + lane;
                    setUnion(t.nodes[child], node, lane);
                    node.child[lane] = static_cast<std::int32_t>(child);
                    t.parent[child] = static_cast<std::int32_t>(FANOUT * (next + j) + lane);
                }
            }
            below = next;
            belowCount = count;
            next += count;
        }
        t.parent[t.nodes.size() - 1] = -1;
    }
}  // namespace ropras::ompl_ext
