#include "ropras/ompl_ext/planners/VectorizedRRTConnect.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/RandomNumbers.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

#include "planners/NodeBlocks.h"
#include "ropras/core/Error.h"
#include "ropras/core/Rng.h"
#include "ropras/ompl_ext/collision/CollisionChecker.h"
#include "ropras/ompl_ext/ompl/MotionValidator.h"
#include "ropras/ompl_ext/ompl/PlannerRegistry.h"
#include "ropras/ompl_ext/planners/HaltonSequence.h"

namespace ropras::ompl_ext
{
    namespace
    {
        constexpr double INF = std::numeric_limits<double>::infinity();
        const double *values(const ompl::base::State *state)
        {
            return state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
        }
    }  // namespace

    VectorizedRRTConnect::VectorizedRRTConnect(const ompl::base::SpaceInformationPtr &si)
        : ompl::base::Planner(si, "VectorizedRRTConnect")
    {
        for (Tree &tree : trees_)
            tree.blocks = std::make_unique<NodeBlocks>();
        specs_.recognizedGoal = ompl::base::GOAL_SAMPLEABLE_REGION;
        specs_.directed = true;
        Planner::declareParam<double>("range", this, &VectorizedRRTConnect::setRange, &VectorizedRRTConnect::getRange,
                                      "0.:0.1:10.");
        Planner::declareParam<bool>("halton", this, &VectorizedRRTConnect::setHalton, &VectorizedRRTConnect::getHalton,
                                    "0,1");
        Planner::declareParam<bool>("balance", this, &VectorizedRRTConnect::setBalance,
                                    &VectorizedRRTConnect::getBalance, "0,1");
        Planner::declareParam<bool>("dynamic_domain", this, &VectorizedRRTConnect::setDynamicDomain,
                                    &VectorizedRRTConnect::getDynamicDomain, "0,1");
        Planner::declareParam<double>("dd_radius", this, &VectorizedRRTConnect::setDynamicDomainRadius,
                                      &VectorizedRRTConnect::getDynamicDomainRadius, "0.:0.1:20.");
        Planner::declareParam<double>("dd_alpha", this, &VectorizedRRTConnect::setDynamicDomainAlpha,
                                      &VectorizedRRTConnect::getDynamicDomainAlpha, "0.:0.0001:1.");
        Planner::declareParam<double>("dd_min_radius", this, &VectorizedRRTConnect::setDynamicDomainMinRadius,
                                      &VectorizedRRTConnect::getDynamicDomainMinRadius, "0.:0.1:10.");
        Planner::declareParam<bool>("dd_connect", this, &VectorizedRRTConnect::setDynamicDomainConnect,
                                    &VectorizedRRTConnect::getDynamicDomainConnect, "0,1");
        Planner::declareParam<double>("tree_ratio", this, &VectorizedRRTConnect::setTreeRatio,
                                      &VectorizedRRTConnect::getTreeRatio, "0.:0.1:10.");
        Planner::declareParam<bool>("direct", this, &VectorizedRRTConnect::setDirectConnection,
                                    &VectorizedRRTConnect::getDirectConnection, "0,1");
        Planner::declareParam<bool>("batch_ends", this, &VectorizedRRTConnect::setBatchEnds,
                                    &VectorizedRRTConnect::getBatchEnds, "0,1");
        Planner::declareParam<unsigned>("batch_after", this, &VectorizedRRTConnect::setBatchAfter,
                                        &VectorizedRRTConnect::getBatchAfter, "0:1:1000000");
        addPlannerProgressProperty("motion checks INTEGER", [this] { return std::to_string(motionChecks_); });
        addPlannerProgressProperty("end batches INTEGER", [this] { return std::to_string(endBatches_); });
        addPlannerProgressProperty("ends rejected INTEGER", [this] { return std::to_string(endsRejected_); });
        Planner::declareParam<unsigned>("max_samples", this, &VectorizedRRTConnect::setMaxSamples,
                                        &VectorizedRRTConnect::getMaxSamples, "0:1:1000000");
        Planner::declareParam<unsigned>("seed", this, &VectorizedRRTConnect::setSeed, &VectorizedRRTConnect::getSeed,
                                        "0:1:1000000");
    }

    void VectorizedRRTConnect::setSeed(unsigned seed)
    {
        seed_ = seed;
        shift_.clear();  // recomputed at the next setup()
    }

    VectorizedRRTConnect::~VectorizedRRTConnect()
    {
        if (sampleState_ != nullptr)
            si_->freeState(sampleState_);
    }

    void VectorizedRRTConnect::setup()
    {
        Planner::setup();
        auto *space = dynamic_cast<const ompl::base::RealVectorStateSpace *>(si_->getStateSpace().get());
        if (space == nullptr)
            throw Error("VectorizedRRTConnect needs a RealVectorStateSpace (got " + si_->getStateSpace()->getName() +
                        ")");
        if (!(range_ > 0.0) || !std::isfinite(range_))
            throw Error("VectorizedRRTConnect: range must be finite and > 0 (got " + std::to_string(range_) + ")");
        if (!(treeRatio_ >= 0.0) || !std::isfinite(treeRatio_))
            throw Error("VectorizedRRTConnect: tree_ratio must be finite and >= 0 (got " + std::to_string(treeRatio_) +
                        ")");
        if (space->getDimension() > NodeBlocks::MAX_DOF)
            throw Error("VectorizedRRTConnect supports at most " + std::to_string(NodeBlocks::MAX_DOF) +
                        " dimensions (the state space " + space->getName() + " has " +
                        std::to_string(space->getDimension()) + ")");
        dof_ = space->getDimension();
        if (!dynamicDomainSet_)
            dynamicDomain_ = dof_ <= DYNAMIC_DOMAIN_MAX_DOF;
        lower_ = space->getBounds().low;
        upper_ = space->getBounds().high;
        // the sample transform runs 4 joints at a time: its arrays and buffers are padded to a multiple of 4
        // (padding: shift, lower and width 0, so padded lanes compute 0)
        dofPadded_ = (dof_ + 3) / 4 * 4;
        scratch_.assign(3 * dofPadded_, 0.0);
        pendingQ_.assign(BATCH_ENDS * dof_, 0.0);
        sampleF_.assign(dofPadded_, 0.0f);
        lowerPadded_.assign(dofPadded_, 0.0);
        widthPadded_.assign(dofPadded_, 0.0);
        for (std::size_t k = 0; k < dof_; ++k)
        {
            lowerPadded_[k] = lower_[k];
            widthPadded_[k] = upper_[k] - lower_[k];
        }
        // Float rounding of a squared distance between two configurations within the bounds: each coordinate is
        // off by at most delta = 2^-24 |q| (query and node), so |d_float - d_double| <= 2 delta sqrt(dof) d +
        // dof delta^2 plus the float summation (relative dof 2^-24, covered by the 0.1 % in nearest()); twice that.
        double magnitude = 0.0;
        for (std::size_t k = 0; k < dof_; ++k)
            magnitude = std::max({magnitude, std::abs(lower_[k]), std::abs(upper_[k])});
        const double delta = 2.0 * 0x1.0p-24 * magnitude;
        floatSlack_[0] = 4.0 * delta * std::sqrt(static_cast<double>(dof_));
        floatSlack_[1] = 2.0 * static_cast<double>(dof_) * delta * delta + 1e-300;
        for (Tree &tree : trees_)
            tree.blocks->reset(dof_);  // the block layout depends on dof_
        reserveTrees(1024);
        if (dof_ <= HaltonSequence::MAX_DIMENSIONS)
            halton_.reset(dof_);
        if (!sampler_)
        {
            sampler_ = si_->allocStateSampler();
            sampleState_ = si_->allocState();
        }
        if (shift_.size() != dof_)
        {
            // Cranley-Patterson rotation of the Halton sequence, from OMPL's seeded RNG or from seed_.
            shift_.resize(dof_);
            if (seed_ == 0)
            {
                ompl::RNG rng;
                for (double &s : shift_)
                    s = rng.uniform01();
            }
            else
            {
                std::uint64_t x = seed_;
                for (double &s : shift_)
                    s = static_cast<double>(core::Rng::splitMix64(x) >> 11) * 0x1.0p-53;
            }
        }
        shiftPadded_.assign(dofPadded_, 0.0);
        std::copy(shift_.begin(), shift_.end(), shiftPadded_.begin());
    }

    void VectorizedRRTConnect::reserveTrees(std::size_t nodes)
    {
        for (Tree &tree : trees_)
        {
            tree.q.reserve(nodes * dof_);
            tree.blocks->reserve(nodes);
            tree.parent.reserve(nodes);
            tree.radius.reserve(nodes);
        }
    }

    void VectorizedRRTConnect::clear()
    {
        Planner::clear();
        for (Tree &tree : trees_)  // vector::clear keeps the capacity: the next solve does not allocate
        {
            tree.q.clear();
            tree.blocks->clear();
            tree.parent.clear();
            tree.radius.clear();
        }
        // The Halton sequence continues across queries (a retry after clear() draws new samples).
    }

    bool VectorizedRRTConnect::motionValid(const double *a, const double *b)
    {
        ++motionChecks_;
        if (checker_ != nullptr)
            return checker_->isMotionValid(*environment_, a, b, resolution_);
        // Generic fallback through OMPL's interface for other validators.
        ompl::base::State *sa = si_->allocState(), *sb = si_->allocState();
        std::copy(a, a + dof_, sa->as<ompl::base::RealVectorStateSpace::StateType>()->values);
        std::copy(b, b + dof_, sb->as<ompl::base::RealVectorStateSpace::StateType>()->values);
        const bool ok = si_->checkMotion(sa, sb);
        si_->freeState(sa);
        si_->freeState(sb);
        return ok;
    }

    std::size_t VectorizedRRTConnect::nearest(const Tree &tree, const double *q, const float *qf, double &distSq,
                                              bool &rejected, bool domain) const
    {
        // the float block scan picks the node, the exact distance to it is computed in double
        float distF = 0.0f;
        std::size_t best;
        if (qf != nullptr)
            best = tree.blocks->nearest(qf, &distF);
        else
        {
            float converted[NodeBlocks::MAX_DOF];
            for (std::size_t k = 0; k < dof_; ++k)
                converted[k] = static_cast<float>(q[k]);
            best = tree.blocks->nearest(converted, &distF);
        }
        // Dynamic domain: most samples lie clearly outside their nearest node's radius. Beyond r^2 plus a bound on
        // the float rounding (floatSlack_, from the joint bounds) the double test would reject too: skip computing
        // it. Closer calls (and every accepted sample) take the exact test in propose().
        rejected = false;
        if (domain)
        {
            const double r = tree.radius[best];
            if (static_cast<double>(distF) > r * r * 1.001 + floatSlack_[0] * r + floatSlack_[1])
            {
                rejected = true;
                return best;
            }
        }
        const double *node = tree.q.data() + best * dof_;
        double d = 0.0;
        for (std::size_t k = 0; k < dof_; ++k)
        {
            const double e = node[k] - q[k];
            d += e * e;
        }
        distSq = d;
        return best;
    }

    void VectorizedRRTConnect::addNode(Tree &tree, const double *q, int parent)
    {
        tree.blocks->add(q);
        tree.q.insert(tree.q.end(), q, q + dof_);
        tree.parent.push_back(parent);
        tree.radius.push_back(INF);
    }

    void VectorizedRRTConnect::sample(double *out, float *outF)
    {
        if (useHalton_ && dof_ <= HaltonSequence::MAX_DIMENSIONS)
        {
            halton_.next(out);
            // shifted point u = h + shift mod 1 (both in [0, 1)), then lower + u * width, also in float
            const double *shift = shiftPadded_.data(), *lower = lowerPadded_.data(), *width = widthPadded_.data();
#if defined(__AVX2__) && defined(__FMA__)
            const __m256d oneV = _mm256_set1_pd(1.0);
            for (std::size_t k = 0; k < dofPadded_; k += 4)
            {
                __m256d u = _mm256_add_pd(_mm256_loadu_pd(out + k), _mm256_loadu_pd(shift + k));
                u = _mm256_sub_pd(u, _mm256_and_pd(_mm256_cmp_pd(u, oneV, _CMP_GE_OQ), oneV));
                const __m256d q =
                    _mm256_add_pd(_mm256_loadu_pd(lower + k), _mm256_mul_pd(u, _mm256_loadu_pd(width + k)));
                _mm256_storeu_pd(out + k, q);
                _mm_storeu_ps(outF + k, _mm256_cvtpd_ps(q));
            }
#else
            for (std::size_t k = 0; k < dof_; ++k)
            {
                double u = out[k] + shift[k];
                u = u < 1.0 ? u : u - 1.0;
                out[k] = lower[k] + u * width[k];
                outF[k] = static_cast<float>(out[k]);
            }
#endif
            return;
        }
        sampler_->sampleUniform(sampleState_);
        std::copy(values(sampleState_), values(sampleState_) + dof_, out);
        for (std::size_t k = 0; k < dof_; ++k)
            outF[k] = static_cast<float>(out[k]);
    }

    bool VectorizedRRTConnect::propose(const Tree &tree, const double *target, int fromNode, const float *targetF,
                                       bool connect, std::size_t &near, double *to, bool &reached) const
    {
        double distSq;
        const bool domain = usesDomain(connect);
        reached = false;
        if (fromNode < 0)
        {
            bool rejected;
            near = nearest(tree, target, targetF, distSq, rejected, domain);
            if (rejected)
                return false;
        }
        else
        {
            near = static_cast<std::size_t>(fromNode);
            const double *node = tree.q.data() + near * dof_;
            distSq = 0.0;
            for (std::size_t k = 0; k < dof_; ++k)
                distSq += (node[k] - target[k]) * (node[k] - target[k]);
        }
        const double dist = std::sqrt(distSq);
        if (domain && fromNode < 0 && dist > tree.radius[near])
            return false;
        const double *from = tree.q.data() + near * dof_;
        if (dist <= range_)
        {
            std::copy(target, target + dof_, to);
            reached = true;
        }
        else
        {
            // a connection covers the distance in ceil(dist / range) equal steps (the last one is not a short
            // remainder); an extension toward a sample takes one step of range
            const double f = connect ? 1.0 / std::ceil(dist / range_) : range_ / dist;
            for (std::size_t k = 0; k < dof_; ++k)
                to[k] = from[k] + f * (target[k] - from[k]);
        }
        return true;
    }

    int VectorizedRRTConnect::grow(Tree &tree, std::size_t near, const double *to, bool connect, bool endValid)
    {
        const bool domain = usesDomain(connect);
        if (!endValid || !motionValid(tree.q.data() + near * dof_, to))
        {
            if (domain)
                tree.radius[near] = std::isinf(tree.radius[near])
                                        ? ddRadius_
                                        : std::max(tree.radius[near] * (1.0 - ddAlpha_), ddMinRadius_);
            return -1;
        }
        if (domain && !std::isinf(tree.radius[near]))
            tree.radius[near] *= (1.0 + ddAlpha_);
        addNode(tree, to, static_cast<int>(near));
        return static_cast<int>(tree.size() - 1);
    }

    int VectorizedRRTConnect::connect(Tree &tree, const double *target)
    {
        double *to = scratch_.data();
        int last = -1;
        while (true)
        {
            // after the first step, continue from the node just added (the target lies straight ahead)
            std::size_t near;
            bool reached;
            if (!propose(tree, target, last, nullptr, true, near, to, reached))
                return -1;
            last = grow(tree, near, to, true, true);
            if (last < 0)
                return -1;
            if (reached)
                return last;
        }
    }

    int VectorizedRRTConnect::growAndConnect(int a, std::size_t near, const double *to, bool endValid)
    {
        Tree &ta = trees_[a];
        Tree &tb = trees_[1 - a];
        const int added = grow(ta, near, to, false, endValid);
        if (added < 0)
            return -1;
        // Connect: grow the other tree toward the new node in steps of range_.
        double *target = scratch_.data() + 2 * dofPadded_;
        std::copy(ta.q.data() + added * dof_, ta.q.data() + (added + 1) * dof_, target);
        const int last = connect(tb, target);
        if (last < 0)
            return 0;
        // tb's last node equals ta's new node; join through tb's parent of it.
        buildSolution(added, tb.parent[last], a == 0);
        return 1;
    }

    bool VectorizedRRTConnect::growPending()
    {
        const std::size_t count = pendingCount_;
        pendingCount_ = 0;
        ++endBatches_;
        endsRejected_ += checker_->obstacleHitsBatch(*environment_, pendingQ_.data(), count, pendingHit_);
        for (std::size_t i = 0; i < count; ++i)
            if (growAndConnect(pending_[i].tree, pending_[i].near, pendingQ_.data() + i * dof_, !pendingHit_[i]) > 0)
                return true;
        return false;
    }

    bool VectorizedRRTConnect::extendTowardSample(int a, const double *sample)
    {
        bool reached;
        if (batchEnds_ && checker_ != nullptr && failedExtensions_ >= batchAfter_)
        {
            // the extension's end is queued; a full queue checks its ends in one batch, then grows each queued
            // extension in order (setBatchEnds)
            Pending &next = pending_[pendingCount_];
            double *to = pendingQ_.data() + pendingCount_ * dof_;
            if (!propose(trees_[a], sample, -1, sampleF_.data(), false, next.near, to, reached))
                return false;
            next.tree = a;
            return ++pendingCount_ == BATCH_ENDS && growPending();
        }
        std::size_t near;
        double *to = scratch_.data();
        if (!propose(trees_[a], sample, -1, sampleF_.data(), false, near, to, reached))
            return false;
        const int grown = growAndConnect(a, near, to, true);
        failedExtensions_ += grown < 0 ? 1u : 0u;
        return grown > 0;
    }

    void VectorizedRRTConnect::buildSolution(int nodeA, int nodeB, bool aIsStartTree)
    {
        const Tree &startTree = trees_[0], &goalTree = trees_[1];
        const int startNode = aIsStartTree ? nodeA : nodeB;
        const int goalNode = aIsStartTree ? nodeB : nodeA;
        // the path's states are allocated straight into it (one allocation per state, no chain vectors, no copy
        // through a temporary state): start root ... startNode, then goalNode ... goal root
        std::size_t startCount = 0, goalCount = 0;
        for (int n = startNode; n >= 0; n = startTree.parent[n])
            ++startCount;
        for (int n = goalNode; n >= 0; n = goalTree.parent[n])
            ++goalCount;
        auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
        std::vector<ompl::base::State *> &states = path->getStates();
        states.resize(startCount + goalCount, nullptr);
        auto put = [&](const Tree &tree, int n, std::size_t at)
        {
            states[at] = si_->allocState();
            std::copy(tree.q.data() + n * dof_, tree.q.data() + (n + 1) * dof_,
                      states[at]->as<ompl::base::RealVectorStateSpace::StateType>()->values);
        };
        std::size_t at = startCount;
        for (int n = startNode; n >= 0; n = startTree.parent[n])
            put(startTree, n, --at);
        at = startCount;
        for (int n = goalNode; n >= 0; n = goalTree.parent[n])
            put(goalTree, n, at++);
        pdef_->addSolutionPath(path, false, 0.0, getName());
    }

    ompl::base::PlannerStatus VectorizedRRTConnect::solve(const ompl::base::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        auto *goal = dynamic_cast<ompl::base::GoalSampleableRegion *>(pdef_->getGoal().get());
        if (goal == nullptr)
            return ompl::base::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;

        // The ropras validator, when installed: one dynamic_cast per validator, not per solve. The environment
        // and resolution are read every solve (setEnvironment / setResolution may change them between queries).
        const ompl::base::MotionValidator *validator = si_->getMotionValidator().get();
        if (validator != validatorSeen_)
        {
            validatorSeen_ = validator;
            roprasValidator_ = dynamic_cast<const MotionValidator *>(validator);
        }
        checker_ = roprasValidator_ != nullptr ? roprasValidator_->checker().get() : nullptr;
        environment_ = roprasValidator_ != nullptr ? roprasValidator_->environment().get() : nullptr;
        resolution_ = roprasValidator_ != nullptr ? roprasValidator_->resolution() : resolution_;

        pendingCount_ = 0;  // extensions queued when the last solve stopped refer to its trees
        failedExtensions_ = 0;
        while (const ompl::base::State *st = pis_.nextStart())
            addNode(trees_[0], values(st), -1);
        if (trees_[0].size() == 0)
            return ompl::base::PlannerStatus::INVALID_START;

        double *sampleBuf = scratch_.data() + dofPadded_;
        int a = 0;  // tree being extended this iteration
        unsigned samples = 0;
        bool directTried = !direct_;
        // The termination condition costs a clock read and a lock (about 0.1 us with a time limit or an exact
        // solution, as in bench-mbm): evaluate it before the first iteration and then once per 32 units of work, a
        // motion check counting 8 and an iteration 1, i.e. after at most 4 motion checks (a few us) or 32 samples
        // the dynamic domain rejected without any check.
        const auto checks = [this] { return motionChecks_ + endBatches_; };  // a batch of ends counts like a check
        std::uint64_t checksSeen = checks();
        std::uint64_t work = 32;
        while (true)
        {
            work += 1 + 8 * (checks() - checksSeen);
            checksSeen = checks();
            if (work >= 32)
            {
                if (ptc)
                    break;
                work = 0;
            }
            // Keep drawing goal states like OMPL's RRTConnect: always at least one, more as the trees grow
            // (while the goal can give more: a single goal state is sampled once).
            if (trees_[1].size() == 0 || (pis_.getSampledGoalsCount() < trees_[1].size() / 2 &&
                                          pis_.getSampledGoalsCount() < goal->maxSampleCount() && goal->canSample()))
            {
                const ompl::base::State *st = trees_[1].size() == 0 ? pis_.nextGoal(ptc) : pis_.nextGoal();
                if (st != nullptr)
                    addNode(trees_[1], values(st), -1);
                if (trees_[1].size() == 0)
                    return ompl::base::PlannerStatus::INVALID_GOAL;
            }
            if (!directTried)
            {
                // The straight motion from the first start to the first goal state, checked once.
                directTried = true;
                if (motionValid(trees_[0].q.data(), trees_[1].q.data()))
                {
                    buildSolution(0, 0, true);
                    return ompl::base::PlannerStatus::EXACT_SOLUTION;
                }
            }
            if (maxSamples_ != 0 && samples >= maxSamples_)
                break;
            ++samples;

            if (balance_ && treeRatio_ <= 0.0)
                a = trees_[0].size() <= trees_[1].size() ? 0 : 1;
            else if (balance_)
            {
                const double last = static_cast<double>(trees_[a].size());
                const double other = static_cast<double>(trees_[1 - a].size());
                if (std::abs(last - other) / last < treeRatio_)
                    a = 1 - a;
            }
            sample(sampleBuf, sampleF_.data());
            if (extendTowardSample(a, sampleBuf))
                return ompl::base::PlannerStatus::EXACT_SOLUTION;
            if (!balance_)
                a = 1 - a;
        }
        return ompl::base::PlannerStatus::TIMEOUT;
    }

    void VectorizedRRTConnect::getPlannerData(ompl::base::PlannerData &data) const
    {
        Planner::getPlannerData(data);
        std::vector<ompl::base::State *> allocated;
        for (int t = 0; t < 2; ++t)
        {
            const Tree &tree = trees_[t];
            std::vector<unsigned> ids(tree.size());
            for (std::size_t i = 0; i < tree.size(); ++i)
            {
                ompl::base::State *s = si_->allocState();
                allocated.push_back(s);
                std::copy(tree.q.data() + i * dof_, tree.q.data() + (i + 1) * dof_,
                          s->as<ompl::base::RealVectorStateSpace::StateType>()->values);
                const ompl::base::PlannerDataVertex v(s, t + 1);
                ids[i] =
                    tree.parent[i] < 0 ? (t == 0 ? data.addStartVertex(v) : data.addGoalVertex(v)) : data.addVertex(v);
            }
            for (std::size_t i = 0; i < tree.size(); ++i)
                if (tree.parent[i] >= 0)
                {
                    if (t == 0)
                        data.addEdge(ids[tree.parent[i]], ids[i]);
                    else
                        data.addEdge(ids[i], ids[tree.parent[i]]);
                }
        }
        // PlannerData refers to states it does not own: make it own copies, then free ours.
        data.decoupleFromPlanner();
        for (ompl::base::State *s : allocated)
            si_->freeState(s);
    }

    void registerOwnPlanners(PlannerRegistry &registry)
    {
        registry.add("VectorizedRRTConnect", [](const ompl::base::SpaceInformationPtr &si)
                     { return std::make_shared<VectorizedRRTConnect>(si); });
    }
}  // namespace ropras::ompl_ext
