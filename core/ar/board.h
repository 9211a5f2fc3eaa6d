#pragma once
// The calibration and tracking targets, as the command line and the studio write them:
//   chessboard:COLSxROWS:SQUARE                       inner corners along x and y, square side (m)
//   aruco-grid:DICT:COLSxROWS:MARKER:GAP              OpenCV 4.6's aruco::GridBoard
//   charuco:DICT:COLSxROWS:SQUARE:MARKER[:inverted]   squares along x and y; printed white on black
// Lengths in metres. The parser says which part of the text is wrong.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace thespis::core::ar {

enum class BoardKind { Chessboard, ArucoGrid, Charuco };

struct BoardSpec {
    BoardKind kind = BoardKind::Chessboard;
    std::string dictionary;  ///< ArUco dictionary name (DICT_4X4_50, …); empty for a chessboard
    int columns = 0, rows = 0;
    double square = 0;       ///< chessboard / ChArUco square side; ArUco grid: marker side
    double second = 0;       ///< ChArUco: marker side; ArUco grid: the gap between markers
    bool inverted = false;   ///< ChArUco printed white on black
    bool operator==(const BoardSpec&) const = default;
};

Result<BoardSpec> parseBoard(std::string_view text);
/// The text parseBoard() reads back as `board`.
std::string formatBoard(const BoardSpec& board);

/// OpenCV's number for a predefined ArUco dictionary name (DICT_4X4_50 … DICT_APRILTAG_36h11), or
/// −1 for a name it does not have.
int arucoDictionaryId(std::string_view name);
/// How many markers the named dictionary holds (0 for an unknown name).
int arucoDictionarySize(std::string_view name);
/// How many markers the board carries (0 for a chessboard).
int boardMarkerCount(const BoardSpec& board);

/// A chessboard's inner corners in its own plane (z = 0), row after row, in metres.
std::vector<std::array<float, 3>> chessboardCorners(const BoardSpec& board);

} // namespace thespis::core::ar
