#ifndef ROPRAS_OMPL_EXT_VECTORIZED_RRT_CONNECT_H
#define ROPRAS_OMPL_EXT_VECTORIZED_RRT_CONNECT_H

#include <ompl/base/Planner.h>
#include <ompl/base/StateSampler.h>
#include <cstdint>
#include <memory>
#include <vector>

#include "ropras/ompl_ext/planners/HaltonSequence.h"

namespace ropras::ompl_ext
{
    class CollisionChecker;
    class Environment;
    class MotionValidator;
    class NodeBlocks;

    /** \brief Bidirectional RRT-Connect that works on flat joint arrays and validates every extension with
        the raked SIMD motion check (registry name "VectorizedRRTConnect").

        It is an ordinary ompl::base::Planner (SimpleSetup, tools::Benchmark and PlannerRegistry treat it like
        any OMPL planner), but when the SpaceInformation carries ropras' MotionValidator it bypasses OMPL's
        per-state allocation and calls the CollisionChecker directly; with any other validator it falls back
        to SpaceInformation::checkMotion. Ideas from VAMP's RRT-Connect, each a parameter so its effect can
        be measured (`ropras bench-mbm`):
        - low-discrepancy sampling: a Halton sequence with a random shift (Cranley-Patterson rotation,
          seeded from OMPL's RNG) instead of uniform random samples (`halton`);
        - tree balancing: always extend the smaller tree (`balance`);
        - dynamic domain: each node has a radius; samples farther than it from their nearest node are
          rejected; a node's radius is set to `dd_radius` (default 5 rad, the lowest median cost per solve over
          the MotionBenchMaker Panda set, doc/benchmarks.md) when an extension from it first fails, then shrinks
          on each failure and grows on each success (`dynamic_domain`, by default on up to 8 planning joints and
          off above, `dd_radius`, `dd_alpha`, `dd_min_radius`);
        - connection: the other tree greedily extends toward each new node in ceil(d / `range`) equal steps (d:
          the remaining distance; no short last step), from its nearest node first and then from each node it
          just added (no nearest-neighbour search per step);
        - direct connection: before growing any tree, the straight start-goal motion is checked once
          (`direct`); a raked check of an invalid motion usually fails within its first batches;
        - batched extension ends (ropras' own, not VAMP's): once `batch_after` extensions toward samples have
          failed in a solve, the ends of BATCH_ENDS extensions are checked in one SIMD batch first and only those
          clear of the obstacles get a motion check (`batch_ends`, `batch_after`; setBatchEnds).
        Nearest neighbours: a linear scan over a float copy of the nodes, laid out in blocks of 8 (one SIMD
        register per joint), reduced in registers, then the exact distance to the winner in double (trees stay
        small at the median).
        Rejected samples are the common case at the median MotionBenchMaker problem (most samples of a small
        tree fall outside the dynamic domain once its nodes have failed an extension), so their path is kept
        short: the Halton point is drawn 8 dimensions at a time (AVX2), shifted, scaled and converted to float in
        4-wide steps, and a sample whose float distance is clearly beyond its nearest node's radius (beyond r^2
        plus a bound on the float rounding) is rejected without the double distance, which decides closer calls
        exactly as before.
        Per-solve fixed costs are kept out of solve(): tree storage is reserved in setup() and keeps its
        capacity across clear(), the solution path's states are allocated straight into the path (one allocation
        per state, no copies), the sampler state is allocated once, the validator is identified once (one
        dynamic_cast per validator, not per solve), and the termination condition (a clock read and a lock) is
        evaluated once per 32 units of work (a motion check 8, an iteration 1). */
    class VectorizedRRTConnect : public ompl::base::Planner
    {
    public:
        /// the most planning joints for which the dynamic domain is on by default (see setDynamicDomain)
        static constexpr std::size_t DYNAMIC_DOMAIN_MAX_DOF = 8;

        explicit VectorizedRRTConnect(const ompl::base::SpaceInformationPtr &si);
        ~VectorizedRRTConnect() override;

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;
        void setup() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        void setRange(double range) { range_ = range; }
        double getRange() const { return range_; }
        void setHalton(bool on) { useHalton_ = on; }
        bool getHalton() const { return useHalton_; }
        void setBalance(bool on) { balance_ = on; }
        bool getBalance() const { return balance_; }
        /** \brief Dynamic domain on or off (parameter "dynamic_domain"). Unless set, setup() chooses: on for at most
            DYNAMIC_DOMAIN_MAX_DOF planning joints, off above (measured on MotionBenchMaker problems: on helps the
            7-joint Panda and is neutral on the 8-joint Fetch; on the 14-joint Baxter it solved 68 % of 50 problems
            within 1 s against 100 % off, doc/benchmarks.md). getDynamicDomain() tells the choice after setup(). */
        void setDynamicDomain(bool on)
        {
            dynamicDomain_ = on;
            dynamicDomainSet_ = true;
        }
        bool getDynamicDomain() const { return dynamicDomain_; }
        void setDynamicDomainRadius(double r) { ddRadius_ = r; }
        double getDynamicDomainRadius() const { return ddRadius_; }
        void setDynamicDomainAlpha(double a) { ddAlpha_ = a; }
        double getDynamicDomainAlpha() const { return ddAlpha_; }
        void setDynamicDomainMinRadius(double r) { ddMinRadius_ = r; }
        double getDynamicDomainMinRadius() const { return ddMinRadius_; }
        /// whether connections take part in the dynamic domain (parameter "dd_connect", default on): a connection
        /// is refused when its first node's radius is below the distance, and a failed or valid connection step
        /// shrinks or grows the radius of the node it started from. Off: connections leave radii alone (VAMP's).
        void setDynamicDomainConnect(bool on) { ddConnect_ = on; }
        /// balancing rule (parameter "tree_ratio", with balance on): 0 (default) extends the smaller tree in every
        /// iteration; r > 0 is VAMP's rule: switch to the other tree while |a - b| / a < r (a: the size of the
        /// tree extended last, b: the other's), i.e. alternate while the sizes are close, else stay on the smaller
        void setTreeRatio(double r) { treeRatio_ = r; }
        double getTreeRatio() const { return treeRatio_; }
        bool getDynamicDomainConnect() const { return ddConnect_; }
        void setDirectConnection(bool on) { direct_ = on; }
        bool getDirectConnection() const { return direct_; }
        /** \brief Batched extension ends (parameter "batch_ends", default on; only with ropras' validator): once
            batch_after extensions have failed, the end configurations of BATCH_ENDS extensions toward samples are
            checked against the obstacles in one SIMD batch (CollisionChecker::obstacleHitsBatch) before any of their
            motions, and an extension whose end hits fails without its motion check. On cluttered problems most
            extensions fail and most failing ones end in collision (doc/benchmarks.md): one batch of ends replaces
            most of their motion checks. The queued extensions then grow in order from the nodes chosen when queued:
            a node added meanwhile is not their nearest, and a node whose dynamic-domain radius shrank meanwhile is
            not tested again. The tree to extend is chosen when queuing (with balance and tree_ratio 0, the 8 go to
            the same tree, the smaller one then). When the termination condition or max_samples ends a solve, a
            partly filled queue is dropped (up to 7 samples counted but not checked). Off: the trees of earlier
            versions. Progress properties "motion checks", "end batches" and "ends rejected" count since
            construction. */
        void setBatchEnds(bool on) { batchEnds_ = on; }
        bool getBatchEnds() const { return batchEnds_; }
        /// failed extensions toward samples in a solve before its ends are batched (parameter "batch_after"):
        /// until then each extension is checked on its own, so an easy problem is not held back by the queue
        void setBatchAfter(unsigned n) { batchAfter_ = n; }
        unsigned getBatchAfter() const { return batchAfter_; }
        void setMaxSamples(unsigned n) { maxSamples_ = n; }
        unsigned getMaxSamples() const { return maxSamples_; }
        /** \brief Seed of the Halton shift (parameter "seed"): 0 (default) draws the shift from OMPL's RNG at
            the first setup(); any other value derives it from \a seed alone (SplitMix64), so two planner
            instances with the same seed and an iteration bound (max_samples) return the same paths.
            Takes effect at the next setup(). Uniform sampling (halton = 0) always uses OMPL's RNG. */
        void setSeed(unsigned seed);
        unsigned getSeed() const { return seed_; }

    private:
        struct Tree
        {
            std::vector<double> q;               ///< node configurations, row-major
            std::unique_ptr<NodeBlocks> blocks;  ///< the same in float, for nearest() (private header)
            std::vector<int> parent;             ///< -1 for a root
            std::vector<double> radius;          ///< dynamic-domain radius per node
            std::size_t size() const { return parent.size(); }
        };

        bool motionValid(const double *a, const double *b);
        bool stateValid(const double *q) const;
        /// \a qf: \a q in float when the caller has it (nullptr: converted here). \a rejected: \a q is clearly
        /// outside the nearest node's dynamic domain (\a distSq is then not computed; only when \a domain)
        std::size_t nearest(const Tree &tree, const double *q, const float *qf, double &distSq, bool &rejected,
                            bool domain) const;
        void addNode(Tree &tree, const double *q, int parent);
        /// the next sample into \a out and, in float, into \a outF (for the nearest-neighbour scan)
        void sample(double *out, float *outF);
        /// whether an extension (or, with \a connect, a connection step) takes part in the dynamic domain
        bool usesDomain(bool connect) const { return dynamicDomain_ && (!connect || ddConnect_); }
        /** \brief The extension of \a tree toward \a target by at most range_ from its nearest node (or from
            \a fromNode when >= 0, without the dynamic-domain test): the node \a near to grow from and the end \a to
            (dof_ values); \a reached: the end is the target. False when the dynamic domain rejects the target.
            \a targetF: the target in float, or nullptr. \a connect: a connection step, the remaining distance d in
            ceil(d / range_) equal steps (an extension toward a sample takes one step of range_) */
        bool propose(const Tree &tree, const double *target, int fromNode, const float *targetF, bool connect,
                     std::size_t &near, double *to, bool &reached) const;
        /// checks the motion near -> to (not when \a endValid is false: the end is known to collide), updates the
        /// node's dynamic-domain radius, adds the node; returns its index or -1
        int grow(Tree &tree, std::size_t near, const double *to, bool connect, bool endValid);
        /// the connection of \a tree toward \a target; returns the node equal to \a target or -1
        int connect(Tree &tree, const double *target);
        /// grows tree \a a by near -> to (grow), then connects the other tree to the new node: 1 when a solution
        /// was built, 0 when grown only, -1 when the extension failed
        int growAndConnect(int a, std::size_t near, const double *to, bool endValid);
        /// one iteration's extension of tree \a a toward \a sample (its float copy in sampleF_): checked at once, or
        /// queued once batch_after extensions have failed (growPending); true when a solution was built
        bool extendTowardSample(int a, const double *sample);
        /// checks the queued ends in one batch (obstacleHitsBatch), then grows the queued extensions in order
        /// (growAndConnect); true when a solution was built
        bool growPending();
        void buildSolution(int startNode, int goalNode, bool startTreeIsA);
        /// reserves room for \a nodes nodes in both trees
        void reserveTrees(std::size_t nodes);

        Tree trees_[2];  ///< 0: rooted at start states, 1: rooted at goal states
        std::size_t dof_{0};
        std::vector<double> lower_, upper_, scratch_, shift_;
        std::size_t dofPadded_{0};    ///< dof_ rounded up to 4 (the sample transform's step)
        double floatSlack_[2]{0, 0};  ///< float rounding bound of a squared distance: [0] * d + [1]
        std::vector<double> lowerPadded_, widthPadded_, shiftPadded_;
        std::vector<float> sampleF_;  ///< the current sample in float
        HaltonSequence halton_;
        ompl::base::StateSamplerPtr sampler_;
        ompl::base::State *sampleState_{nullptr};
        const ompl::base::MotionValidator *validatorSeen_{nullptr};  ///< the validator checker_ was taken from
        const MotionValidator *roprasValidator_{nullptr};            ///< non-null when it is ropras'
        const CollisionChecker *checker_{nullptr};
        const Environment *environment_{nullptr};
        double resolution_{1.0 / 32.0};

        double range_{1.0};
        bool useHalton_{true};
        bool balance_{true};
        bool dynamicDomain_{true};
        bool dynamicDomainSet_{false};  ///< setDynamicDomain() was called: setup() keeps the choice
        double ddRadius_{5.0};
        double ddAlpha_{1.0e-4};
        double ddMinRadius_{1.0};
        bool direct_{true};
        bool ddConnect_{true};
        double treeRatio_{0.0};
        /// since construction (progress properties): motion checks, batches of ends, ends rejected by a batch; a
        /// motion check or a batch is 8 units of work between two PTC evaluations
        std::uint64_t motionChecks_{0}, endBatches_{0}, endsRejected_{0};
        unsigned maxSamples_{0};  ///< 0: unlimited (until the termination condition)
        unsigned seed_{0};        ///< 0: Halton shift from OMPL's RNG
        /// extensions whose ends are checked in one batch (setBatchEnds)
        static constexpr std::size_t BATCH_ENDS = 8;
        struct Pending
        {
            int tree{0};
            std::size_t near{0};
        };
        bool batchEnds_{true};
        unsigned batchAfter_{32};
        unsigned failedExtensions_{0};  ///< in this solve (toward samples)
        Pending pending_[BATCH_ENDS];
        bool pendingHit_[BATCH_ENDS]{};  ///< the queued ends that hit an obstacle
        std::vector<double> pendingQ_;   ///< the queued ends, BATCH_ENDS x dof_ (sized in setup())
        std::size_t pendingCount_{0};    ///< reset at the start of every solve
    };
}  // namespace ropras::ompl_ext

#endif
