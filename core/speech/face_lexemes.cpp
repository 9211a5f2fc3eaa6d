#include "speech/face_lexemes.h"

#include "util/text.h"

namespace thespis::core::speech {

namespace {

struct Lexeme {
    std::string_view name;
    std::vector<std::pair<int, double>> faps;
};

// FAP 31/33/35 raise the left brow (inner, middle, outer), 32/34/36 the right; 37/38 squeeze
// them; 12/13 raise the mouth corners and 6/7 stretch them; 3 opens the jaw, 4/5 part the lips;
// 19–22 close the lids (1024 IRISD units shut the eye).
const std::vector<Lexeme>& lexemes()
{
    static const std::vector<Lexeme> table = {
        {"RAISE_BROWS", {{31, 300}, {32, 300}, {33, 320}, {34, 320}, {35, 260}, {36, 260}}},
        {"RAISE_LEFT_BROW", {{31, 300}, {33, 320}, {35, 260}}},
        {"RAISE_RIGHT_BROW", {{32, 300}, {34, 320}, {36, 260}}},
        {"LOWER_BROWS", {{31, -220}, {32, -220}, {33, -180}, {34, -180}, {35, -120}, {36, -120}, {37, 100}, {38, 100}}},
        {"LOWER_LEFT_BROW", {{31, -220}, {33, -180}, {35, -120}, {37, 100}}},
        {"LOWER_RIGHT_BROW", {{32, -220}, {34, -180}, {36, -120}, {38, 100}}},
        {"OBLIQUE_BROWS", {{31, 300}, {32, 300}, {33, 120}, {34, 120}, {35, -100}, {36, -100}}},
        {"RAISE_MOUTH_CORNERS", {{12, 200}, {13, 200}, {6, 80}, {7, 80}}},
        {"RAISE_LEFT_MOUTH_CORNER", {{12, 200}, {6, 80}}},
        {"RAISE_RIGHT_MOUTH_CORNER", {{13, 200}, {7, 80}}},
        {"LOWER_MOUTH_CORNERS", {{12, -200}, {13, -200}}},
        {"LOWER_LEFT_MOUTH_CORNER", {{12, -200}}},
        {"LOWER_RIGHT_MOUTH_CORNER", {{13, -200}}},
        {"OPEN_MOUTH", {{3, 500}}},
        {"OPEN_LIPS", {{4, 120}, {5, -120}}},
        {"WIDEN_EYES", {{19, -150}, {20, -150}, {21, -60}, {22, -60}}},
        {"CLOSE_EYES", {{19, 900}, {20, 900}, {21, 124}, {22, 124}}},
    };
    return table;
}

} // namespace

Result<std::vector<std::pair<int, double>>> faceLexemeFaps(std::string_view lexeme)
{
    const std::string upper = uppercase(lexeme);
    for (const Lexeme& l : lexemes())
        if (l.name == upper)
            return l.faps;
    std::string known;
    for (const Lexeme& l : lexemes())
        known += (known.empty() ? "" : ", ") + std::string(l.name);
    return makeError(ErrorCode::NotFound, "\"" + std::string(lexeme) + "\" is no faceLexeme (they are " + known + ").");
}

std::vector<std::string> faceLexemeNames()
{
    std::vector<std::string> names;
    for (const Lexeme& l : lexemes())
        names.emplace_back(l.name);
    return names;
}

} // namespace thespis::core::speech
