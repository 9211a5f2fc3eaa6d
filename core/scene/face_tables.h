#pragma once
// The low-level FAPs of MPEG-4's 14 visemes and 6 expressions at full weight (fap.h), for faces
// that move by FAPs (the built-in humanoid; a model mapped through ARKit-like targets). MPEG-4
// names the visemes by their phonemes and describes the expressions in words (ISO/IEC 14496-2,
// Table C-3: "joy: the eyebrows are relaxed, the mouth is open and the mouth corners pulled back
// toward the ears" …); the FAP values are this project's, in FAP units.

#include <vector>

#include "scene/face_rig.h"

namespace thespis::core::scene {

/// Viseme `number` (1 … 14).
const std::vector<FapValue>& visemeFaps(int number);
/// Expression `number` (1 … 6: joy, sadness, anger, fear, disgust, surprise) at intensity 1.
const std::vector<FapValue>& expressionFaps(int number);

} // namespace thespis::core::scene
