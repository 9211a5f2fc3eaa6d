#pragma once
// What the scenario format tests read: each version's golden file, and the message a document
// the reader refuses gets.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "scenario/scenario_io.h"
#include "test_support.h"

namespace thespis::test {

/// tests/data/formats/v<version>/scenario.thespis, loaded (a test failure when it does not load).
inline core::scenario::Scenario goldenScenario(int version)
{
    auto s = core::scenario::loadScenario(testData("formats/v" + std::to_string(version) + "/scenario.thespis"));
    EXPECT_TRUE(s) << core::describe(s.error());
    return s ? std::move(s).value() : core::scenario::Scenario{};
}

/// Why the reader refuses `document` (a test failure when it reads it).
inline std::string refusedScenario(const nlohmann::json& document)
{
    auto result = core::scenario::parseScenario(document.dump());
    EXPECT_FALSE(result.ok());
    return result ? std::string() : result.error().message;
}

} // namespace thespis::test
