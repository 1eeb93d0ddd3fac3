#ifndef ROPRAS_OMPL_EXT_OBSTACLE_INDEX_H
#define ROPRAS_OMPL_EXT_OBSTACLE_INDEX_H

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace ropras::ompl_ext
{
    class Environment;
    struct ObstacleAabb;

    /// children per ObstacleIndexNode (the SIMD width of the collision kernels)
    constexpr int OBSTACLE_INDEX_FANOUT = 8;

    /** \brief One node of the obstacle index: the world boxes (lo, hi per axis) of its eight children side by side,
        so that a kernel tests eight children against the robot's box with one vector test. In a leaf the children
        are primitives (child[i] indexes Environment::primitiveRef), else nodes. Lanes without a child have
        lo = +infinity and hi = -infinity: no box overlaps them. */
    struct ObstacleIndexNode
    {
        float lox[OBSTACLE_INDEX_FANOUT], loy[OBSTACLE_INDEX_FANOUT], loz[OBSTACLE_INDEX_FANOUT];
        float hix[OBSTACLE_INDEX_FANOUT], hiy[OBSTACLE_INDEX_FANOUT], hiz[OBSTACLE_INDEX_FANOUT];
        std::int32_t child[OBSTACLE_INDEX_FANOUT];
    };

    /** \brief The built tree of an ObstacleIndex: an 8-ary bounding volume hierarchy over the primitives' world
        boxes (ObstacleAabb). The primitives are ordered by a top-down median split of their centres (along the
        longest extent, at multiples of the full subtrees' size); leaves hold eight consecutive primitives of that
        order, every node above eight consecutive nodes of the level below; nodes [0, leafCount) are the leaves, the
        root is the last node. Read by the collision kernels (a traversal costs a vector test per node whose box
       overlaps the robot's), so obstacles out of reach cost nothing but the few nodes above them. */
    struct ObstacleTree
    {
        std::vector<ObstacleIndexNode> nodes;
        std::size_t leafCount{0};
        std::vector<std::int32_t> parent;     ///< per node: OBSTACLE_INDEX_FANOUT * parent + lane, -1 for the root
        std::vector<std::int32_t> slot;       ///< per primitive: OBSTACLE_INDEX_FANOUT * leaf + lane
        std::vector<std::uint64_t> sortKeys;  ///< build scratch (the order of the primitives), kept for rebuilds
        std::int32_t root() const noexcept { return static_cast<std::int32_t>(nodes.size()) - 1; }
        bool isLeaf(std::int32_t node) const noexcept { return static_cast<std::size_t>(node) < leafCount; }
    };

    /** \brief Broad phase of an Environment: an ObstacleTree over its primitives, for Environments with at least
        MIN_PRIMITIVES of them (smaller ones are scanned, which is cheaper).

        Maintained by the Environment: adding objects marks the tree stale (and reserves its memory), moving one
        refits the boxes on its path to the root in O(log n); the tree is (re)built by the first check that needs
        it, under a lock, into the reserved memory (no allocation in a check). Copies of an Environment share the
        tree until one of them changes (copy on write); several threads may check against one Environment. */
    class ObstacleIndex
    {
    public:
        /// Environments with fewer primitives have no tree
        static constexpr std::size_t MIN_PRIMITIVES = 32;
        /// after this many refits per primitive (objects moved far spoil the tree's grouping) the tree is rebuilt
        static constexpr std::size_t REFITS_PER_PRIMITIVE = 4;

        /// the Environment now has \a primitives primitives (objects were added)
        void added(std::size_t primitives);
        /// primitive \a primitive of the Environment moved to \a box
        void moved(std::size_t primitive, const ObstacleAabb &box);
        void clear() noexcept { state_.reset(); }

        /** \brief The tree over \a env's primitives (built now if stale), or nullptr when \a env has fewer than
            MIN_PRIMITIVES primitives. \a env must be the Environment that owns this index. */
        const ObstacleTree *tree(const Environment &env) const noexcept
        {
            if (!state_)
                return nullptr;
            return state_->fresh.load(std::memory_order_acquire) ? &state_->tree : buildTree(env);
        }

    private:
        struct State
        {
            std::mutex mutex;
            std::atomic<bool> fresh{false};
            std::size_t refits{0};
            ObstacleTree tree;
        };
        /// the state, first copied when another Environment shares it
        State &own();
        /// tree() of a stale tree: builds it under the lock
        const ObstacleTree *buildTree(const Environment &env) const noexcept;
        static void build(const Environment &env, ObstacleTree &tree) noexcept;
        std::shared_ptr<State> state_;  ///< null: no tree (fewer than MIN_PRIMITIVES primitives)
    };
}  // namespace ropras::ompl_ext

#endif
