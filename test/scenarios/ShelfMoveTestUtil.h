#ifndef ROPRAS_TEST_SCENARIOS_SHELF_MOVE_TEST_UTIL_H
#define ROPRAS_TEST_SCENARIOS_SHELF_MOVE_TEST_UTIL_H

// What the Shelf-Move tests share: the default configuration and models made from it.
#include <memory>
#include <nlohmann/json.hpp>

#include "ropras/scenarios/ScenarioRegistry.h"
#include "ropras/scenarios/manipulation/ShelfMoveModel.h"

namespace ropras::scenarios::test
{
    inline nlohmann::json shelfMoveJson()
    {
        return nlohmann::json::parse(embeddedFile("manipulation/shelf-move/default.json"));
    }

    inline std::shared_ptr<const ShelfMoveModel> makeShelfMoveModel(const nlohmann::json &json = shelfMoveJson())
    {
        const auto config = ShelfMoveConfig::fromJson(json, "shelf-move");
        return std::make_shared<const ShelfMoveModel>(config, sharedPandaArm(config.endEffector));
    }

    /// the model of the default configuration (made once)
    inline const std::shared_ptr<const ShelfMoveModel> &shelfMoveModel()
    {
        static const auto m = makeShelfMoveModel();
        return m;
    }
}  // namespace ropras::scenarios::test

#endif
