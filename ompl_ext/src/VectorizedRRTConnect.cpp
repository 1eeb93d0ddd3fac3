#include "ropras/ompl_ext/VectorizedRRTConnect.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/RandomNumbers.h>
#include <cmath>
#include <limits>

#include "ropras/core/Error.h"
#include "ropras/ompl_ext/CollisionChecker.h"
#include "ropras/ompl_ext/HaltonSequence.h"
#include "ropras/ompl_ext/MotionValidator.h"
#include "ropras/ompl_ext/PlannerRegistry.h"

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
        dof_ = space->getDimension();
        lower_ = space->getBounds().low;
        upper_ = space->getBounds().high;
        scratch_.assign(3 * dof_, 0.0);
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
                {
                    std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
                    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
                    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
                    s = static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
                }
            }
        }
    }

    void VectorizedRRTConnect::clear()
    {
        Planner::clear();
        for (Tree &tree : trees_)
        {
            tree.q.clear();
            tree.parent.clear();
            tree.radius.clear();
        }
        // The Halton sequence continues across queries (a retry after clear() draws new samples).
    }

    bool VectorizedRRTConnect::motionValid(const double *a, const double *b) const
    {
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

    std::size_t VectorizedRRTConnect::nearest(const Tree &tree, const double *q, double &distSq) const
    {
        std::size_t best = 0;
        distSq = INF;
        const double *node = tree.q.data();
        for (std::size_t i = 0; i < tree.size(); ++i, node += dof_)
        {
            double d = 0.0;
            for (std::size_t k = 0; k < dof_; ++k)
            {
                const double e = node[k] - q[k];
                d += e * e;
            }
            if (d < distSq)
            {
                distSq = d;
                best = i;
            }
        }
        return best;
    }

    void VectorizedRRTConnect::addNode(Tree &tree, const double *q, int parent)
    {
        tree.q.insert(tree.q.end(), q, q + dof_);
        tree.parent.push_back(parent);
        tree.radius.push_back(INF);
    }

    void VectorizedRRTConnect::sample(double *out)
    {
        if (useHalton_ && dof_ <= HaltonSequence::MAX_DIMENSIONS)
        {
            halton_.next(out);
            for (std::size_t k = 0; k < dof_; ++k)
            {
                double u = out[k] + shift_[k];
                u -= std::floor(u);
                out[k] = lower_[k] + u * (upper_[k] - lower_[k]);
            }
            return;
        }
        sampler_->sampleUniform(sampleState_);
        std::copy(values(sampleState_), values(sampleState_) + dof_, out);
    }

    int VectorizedRRTConnect::extend(Tree &tree, const double *target, bool &reached)
    {
        double distSq;
        const std::size_t near = nearest(tree, target, distSq);
        const double dist = std::sqrt(distSq);
        reached = false;
        if (dynamicDomain_ && dist > tree.radius[near])
            return -1;
        const double *from = tree.q.data() + near * dof_;
        double *to = scratch_.data();
        if (dist <= range_)
        {
            std::copy(target, target + dof_, to);
            reached = true;
        }
        else
        {
            const double f = range_ / dist;
            for (std::size_t k = 0; k < dof_; ++k)
                to[k] = from[k] + f * (target[k] - from[k]);
        }
        if (!motionValid(from, to))
        {
            if (dynamicDomain_)
                tree.radius[near] = std::isinf(tree.radius[near])
                                        ? ddRadius_
                                        : std::max(tree.radius[near] * (1.0 - ddAlpha_), ddMinRadius_);
            reached = false;
            return -1;
        }
        if (dynamicDomain_ && !std::isinf(tree.radius[near]))
            tree.radius[near] *= (1.0 + ddAlpha_);
        addNode(tree, to, static_cast<int>(near));
        return static_cast<int>(tree.size() - 1);
    }

    void VectorizedRRTConnect::buildSolution(int nodeA, int nodeB, bool aIsStartTree)
    {
        const Tree &startTree = trees_[0], &goalTree = trees_[1];
        const int startNode = aIsStartTree ? nodeA : nodeB;
        const int goalNode = aIsStartTree ? nodeB : nodeA;
        std::vector<int> startChain, goalChain;
        for (int n = startNode; n >= 0; n = startTree.parent[n])
            startChain.push_back(n);
        for (int n = goalNode; n >= 0; n = goalTree.parent[n])
            goalChain.push_back(n);
        auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
        ompl::base::State *state = si_->allocState();
        auto append = [&](const Tree &tree, int n)
        {
            std::copy(tree.q.data() + n * dof_, tree.q.data() + (n + 1) * dof_,
                      state->as<ompl::base::RealVectorStateSpace::StateType>()->values);
            path->append(state);
        };
        for (auto it = startChain.rbegin(); it != startChain.rend(); ++it)
            append(startTree, *it);
        for (int n : goalChain)
            append(goalTree, n);
        si_->freeState(state);
        pdef_->addSolutionPath(path, false, 0.0, getName());
    }

    ompl::base::PlannerStatus VectorizedRRTConnect::solve(const ompl::base::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        auto *goal = dynamic_cast<ompl::base::GoalSampleableRegion *>(pdef_->getGoal().get());
        if (goal == nullptr)
            return ompl::base::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;

        auto mv = std::dynamic_pointer_cast<const MotionValidator>(si_->getMotionValidator());
        checker_ = mv ? mv->checker().get() : nullptr;
        environment_ = mv ? mv->environment().get() : nullptr;
        resolution_ = mv ? mv->resolution() : resolution_;

        while (const ompl::base::State *st = pis_.nextStart())
            addNode(trees_[0], values(st), -1);
        if (trees_[0].size() == 0)
            return ompl::base::PlannerStatus::INVALID_START;

        double *sampleBuf = scratch_.data() + dof_;
        double *targetBuf = scratch_.data() + 2 * dof_;
        int a = 0;  // tree being extended this iteration
        unsigned samples = 0;
        while (!ptc)
        {
            // Keep drawing goal states like OMPL's RRTConnect: always at least one, more as the trees grow.
            if (trees_[1].size() == 0 || pis_.getSampledGoalsCount() < trees_[1].size() / 2)
            {
                const ompl::base::State *st = trees_[1].size() == 0 ? pis_.nextGoal(ptc) : pis_.nextGoal();
                if (st != nullptr)
                    addNode(trees_[1], values(st), -1);
                if (trees_[1].size() == 0)
                    return ompl::base::PlannerStatus::INVALID_GOAL;
            }
            if (maxSamples_ != 0 && samples >= maxSamples_)
                break;
            ++samples;

            if (balance_)
                a = trees_[0].size() <= trees_[1].size() ? 0 : 1;
            Tree &ta = trees_[a];
            Tree &tb = trees_[1 - a];
            sample(sampleBuf);
            bool reached;
            const int added = extend(ta, sampleBuf, reached);
            if (added >= 0)
            {
                // Connect: grow the other tree toward the new node in steps of range_.
                std::copy(ta.q.data() + added * dof_, ta.q.data() + (added + 1) * dof_, targetBuf);
                int last = -1;
                bool connected = false;
                while (true)
                {
                    bool hit;
                    const int node = extend(tb, targetBuf, hit);
                    if (node < 0)
                        break;
                    last = node;
                    if (hit)
                    {
                        connected = true;
                        break;
                    }
                }
                if (connected)
                {
                    // tb's last node equals ta's new node; join through tb's parent of it.
                    buildSolution(added, tb.parent[last], a == 0);
                    return ompl::base::PlannerStatus::EXACT_SOLUTION;
                }
            }
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
