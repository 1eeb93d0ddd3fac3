// ShelfMoveModel::graspableLayout: whether a drawn layout of cans can be cleared, grasp after grasp, down to the
// target.
#include <algorithm>
#include <array>
#include <memory>

#include "ropras/scenarios/manipulation/ShelfMoveModel.h"
#include "ropras/scenarios/manipulation/ShelfMovePlanning.h"

namespace ropras::scenarios
{
    namespace
    {
        /// parks can \a k of \a s on the first slot (not the reserved one) where it may stand; false when none is free
        bool park(const ShelfMoveModel &model, ShelfMoveModel::State &s, std::size_t k) noexcept
        {
            const auto &config = model.config();
            for (std::size_t i = 0; i < config.slots.size(); ++i)
            {
                if (i == config.reservedSlot)
                {
                    continue;
                }
                const ShelfMoveModel::State parked = model.placedOnSlot(s, k, i);
                if (model.canPlacementValid(parked, k))
                {
                    s = parked;
                    return true;
                }
            }
            return false;
        }
    }  // namespace

    bool ShelfMoveModel::graspableLayout(const State &s, pomdp::Rng &rng) const noexcept
    {
        if (s.held >= 0)
        {
            return false;
        }
        try
        {
            // non-owning: the solver lives only for this call, inside the model's lifetime
            const std::shared_ptr<const ShelfMoveModel> self(std::shared_ptr<const ShelfMoveModel>(), this);
            ShelfMoveIk ik(self, std::max(config_.ikRestarts, LAYOUT_IK_RESTARTS), rng());
            State layout = s;
            std::array<bool, SHELF_CANS> taken{};
            const std::size_t target = config_.targetCan;
            for (std::size_t round = 0; round < SHELF_CANS; ++round)
            {
                const auto scene = makeScene(layout, true);
                bool progress = false;
                // the target first: once it is graspable, the layout is
                for (std::size_t n = 0; n < SHELF_CANS && !progress; ++n)
                {
                    const std::size_t k = n == 0 ? target : (n <= target ? n - 1 : n);
                    if (taken[k])
                    {
                        continue;
                    }
                    double q[ARM_DOF];
                    if (!ik.solve(layout, ShelfMoveTargetSpace::grasp(layout, static_cast<int>(k)), *scene, q))
                    {
                        continue;
                    }
                    if (k == target)
                    {
                        return true;
                    }
                    if (!park(*this, layout, k))
                    {
                        return false;
                    }
                    taken[k] = true;
                    progress = true;
                }
                if (!progress)
                {
                    return false;
                }
            }
            return false;
        }
        catch (...)
        {
            return false;  // out of memory for a scene or the IK workspace: not shown graspable
        }
    }
}  // namespace ropras::scenarios
