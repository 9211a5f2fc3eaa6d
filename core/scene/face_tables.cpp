#include "scene/face_tables.h"

#include <array>
#include <cassert>

namespace thespis::core::scene {

namespace {

// FAP numbers: 3 open_jaw, 4 lower_t_midlip, 5 raise_b_midlip, 6/7 stretch corners, 8/9 lower
// upper lip's sides, 10/11 raise lower lip's sides, 12/13 raise corners, 16/17 push lips, 19–22
// lids, 31–36 brows, 37/38 squeeze brows, 41/42 lift cheeks, 44 raise tongue tip, 45 thrust
// tongue tip, 46 raise tongue, 51–60 the outer lip contour's counterparts, 61–63 nose.
const std::array<std::vector<FapValue>, kVisemeCount> kVisemes{{
    // 1 p, b, m: the lips closed and pressed.
    {{3, 0}, {4, 70}, {5, 90}, {8, 55}, {9, 55}, {10, 65}, {11, 65}, {16, 40}, {17, 40}},
    // 2 f, v: the lower lip up under the upper teeth.
    {{3, 60}, {4, -60}, {5, 150}, {10, 120}, {11, 120}, {16, -120}, {51, -40}},
    // 3 T, D: the tongue's tip between the teeth.
    {{3, 120}, {44, 60}, {45, 250}, {4, -30}},
    // 4 t, d: the tip up behind the upper teeth.
    {{3, 100}, {44, 250}, {45, 80}},
    // 5 k, g: the tongue's back up.
    {{3, 150}, {46, 200}},
    // 6 tS, dZ, S: the lips pushed out and a little rounded.
    {{3, 80}, {17, 150}, {16, 150}, {6, -80}, {7, -80}, {4, -60}, {5, -60}},
    // 7 s, z: the teeth nearly closed, the lips apart and spread.
    {{3, 40}, {6, 80}, {7, 80}, {4, -80}, {5, -100}},
    // 8 n, l: the tip up.
    {{3, 120}, {44, 280}},
    // 9 r: the lips a little rounded, the tongue up.
    {{3, 100}, {16, 100}, {17, 100}, {6, -60}, {7, -60}, {46, 80}},
    // 10 A: (car): wide open.
    {{3, 400}, {6, 30}, {7, 30}, {4, -40}},
    // 11 e (bed): open, the corners back.
    {{3, 250}, {6, 120}, {7, 120}, {4, -60}, {5, -30}},
    // 12 I (tip): half open, spread.
    {{3, 150}, {6, 160}, {7, 160}, {12, 40}, {13, 40}, {4, -60}},
    // 13 Q (top): open and rounded.
    {{3, 320}, {6, -120}, {7, -120}, {16, 100}, {17, 100}},
    // 14 U (book): rounded and pushed out.
    {{3, 120}, {6, -220}, {7, -220}, {16, 250}, {17, 250}, {4, -40}, {5, -40}},
}};

const std::array<std::vector<FapValue>, kExpressionCount> kExpressions{{
    // joy: the corners back and up, the cheeks lifted, the lower lids up, the mouth a little open.
    {{6, 230}, {7, 230}, {12, 260}, {13, 260}, {53, 200}, {54, 200}, {59, 220}, {60, 220}, {41, 180}, {42, 180},
     {21, 200}, {22, 200}, {3, 80}, {4, -40}},
    // sadness: the inner brows up and together, the upper lids down, the corners down.
    {{31, 150}, {32, 150}, {33, 60}, {34, 60}, {35, -60}, {36, -60}, {37, 40}, {38, 40}, {19, 250}, {20, 250},
     {12, -120}, {13, -120}, {59, -120}, {60, -120}, {5, 40}},
    // anger: the inner brows down and together, the eyes wide, the lips pressed, the nostrils wide.
    {{31, -200}, {32, -200}, {33, -120}, {34, -120}, {37, 120}, {38, 120}, {19, -150}, {20, -150}, {21, 150},
     {22, 150}, {4, 40}, {5, 60}, {6, -40}, {7, -40}, {61, 150}, {62, 150}},
    // fear: the brows up and together, the upper lids up, the mouth open and stretched.
    {{31, 200}, {32, 200}, {33, 150}, {34, 150}, {35, 100}, {36, 100}, {37, 80}, {38, 80}, {19, -250}, {20, -250},
     {3, 150}, {6, 150}, {7, 150}, {12, -60}, {13, -60}},
    // disgust: the upper lip raised, the nose wrinkled, the brows down, the lower lids up.
    {{4, -150}, {8, -120}, {9, -120}, {51, -150}, {63, 120}, {61, 100}, {62, 100}, {31, -100}, {32, -100}, {21, 150},
     {22, 150}, {12, -80}, {13, -80}, {6, 40}},
    // surprise: the brows high, the upper lids up, the jaw dropped.
    {{31, 300}, {32, 300}, {33, 280}, {34, 280}, {35, 220}, {36, 220}, {19, -300}, {20, -300}, {3, 400}, {6, -80},
     {7, -80}},
}};

} // namespace

const std::vector<FapValue>& visemeFaps(int number)
{
    assert(number >= 1 && number <= kVisemeCount);
    return kVisemes[std::size_t(number - 1)];
}

const std::vector<FapValue>& expressionFaps(int number)
{
    assert(number >= 1 && number <= kExpressionCount);
    return kExpressions[std::size_t(number - 1)];
}

} // namespace thespis::core::scene
