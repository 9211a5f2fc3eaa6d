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

const Gesture* Character::findGesture(const std::string& gestureName) const
{
    for (const Gesture& gesture : gestures)
        if (gesture.name == gestureName)
            return &gesture;
    return nullptr;
}

const ClipAsset* Character::findClip(const std::string& clipName) const
{
    for (const ClipAsset& clip : clips)
        if (clip.name == clipName)
            return &clip;
    return nullptr;
}

} // namespace thespis::core::scenario
