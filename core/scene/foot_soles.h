#pragma once
// Where a character's feet meet the floor, taken from its mesh: the vertices of each foot that
// touch the floor first however the foot is turned (its support points downwards and obliquely
// down all around: heel, toes, the edges of the sole), fixed to their segment's joint. Retargeting
// onto the character keeps these on the floor where the motion's feet are on it
// (anim::RetargetOptions::targetSoles), so a shoe's toe does not dip through the ground where a
// skeleton-only guess of the sole would let it.

#include <vector>

#include "anim/body_measure.h"
#include "anim/hanim.h"
#include "scene/character.h"

namespace thespis::core::scene {

/// Sole points of the foot segments (those following an ankle or a joint below it); empty when
/// the character has no feet.
std::vector<anim::BodyMeasure::SolePoint> footSoles(const Character& character);

/// The soles of the built-in humanoid (scene/default_humanoid.h) at a level, made once.
const std::vector<anim::BodyMeasure::SolePoint>& defaultHumanoidSoles(anim::hanim::Level level);

} // namespace thespis::core::scene
