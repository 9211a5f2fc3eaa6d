#include "scenario/scenario.h"

namespace thespis::core::scenario {

const Character* Scenario::findCharacter(const std::string& characterName) const
{
    for (const Character& character : characters)
        if (character.name == characterName)
            return &character;
    return nullptr;
}

const NamedMask* Scenario::findMask(const std::string& maskName) const
{
    for (const NamedMask& mask : masks)
        if (mask.name == maskName)
            return &mask;
    return nullptr;
}

} // namespace thespis::core::scenario
