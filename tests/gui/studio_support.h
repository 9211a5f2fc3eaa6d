#pragma once
// Helpers of the tests on the studio window: finding a character by name, and how much of a
// picture changed.

#include <QImage>

#include <cstdlib>
#include <string>

#include "editor/document.h"

namespace thespis::test {

inline int characterIndex(const editor::Document& document, const std::string& name)
{
    const auto& characters = document.scenario().characters;
    for (std::size_t c = 0; c < characters.size(); ++c)
        if (characters[c].name == name)
            return int(c);
    return -1;
}

// How many pixels differ by more than a few levels over the channels.
inline int changedPixels(const QImage& a, const QImage& b)
{
    if (a.size() != b.size())
        return a.width() * a.height();
    int changed = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            changed += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q)) > 24;
        }
    return changed;
}

} // namespace thespis::test
