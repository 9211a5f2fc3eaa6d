#pragma once
// BML 1.0's faceLexemes as MPEG-4 facial animation parameters: each lexeme (RAISE_BROWS,
// OPEN_MOUTH, …) is a handful of FAPs moved by a set amount in their units (FAPU: a face distance
// over 1024), so that any face of the faces issue — the humanoid's, a glTF model's through its
// mapping table — shows it. At amount 1: brows up about 1 cm, mouth corners 4 mm, the jaw 1 cm.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "util/error.h"

namespace thespis::core::speech {

/// The FAPs (number, value at amount 1) of a faceLexeme, in any case. Error: not one of BML's.
Result<std::vector<std::pair<int, double>>> faceLexemeFaps(std::string_view lexeme);
/// The faceLexemes known, as BML spells them.
std::vector<std::string> faceLexemeNames();

} // namespace thespis::core::speech
