#include "ar/board.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace thespis::core::ar {

namespace {

std::vector<std::string_view> split(std::string_view text, char separator)
{
    std::vector<std::string_view> parts;
    for (std::size_t at = 0;;) {
        const std::size_t next = text.find(separator, at);
        parts.push_back(text.substr(at, next == std::string_view::npos ? std::string_view::npos : next - at));
        if (next == std::string_view::npos)
            return parts;
        at = next + 1;
    }
}

// "text" with its quotes (built by appending: GCC 12 warns falsely on "\"" + std::string).
std::string quoted(std::string_view text)
{
    std::string result(1, '"');
    result += text;
    result += '"';
    return result;
}

Error wrong(std::string_view text, const std::string& what)
{
    return makeError(ErrorCode::InvalidArgument, "Board \"" + std::string(text) + "\": " + what);
}

bool positiveLength(std::string_view part, double& value)
{
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    return error == std::errc() && end == part.data() + part.size() && std::isfinite(value) && value > 0;
}

bool gridSize(std::string_view part, int& columns, int& rows)
{
    const std::size_t x = part.find('x');
    if (x == std::string_view::npos)
        return false;
    const auto parse = [](std::string_view digits, int& value) {
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        return error == std::errc() && end == digits.data() + digits.size() && value > 0 && value < 1000;
    };
    return parse(part.substr(0, x), columns) && parse(part.substr(x + 1), rows);
}

struct Dictionary {
    std::string_view name;
    int markers;
};
// In the order of OpenCV 4.6's PREDEFINED_DICTIONARY_NAME: the index is its number.
constexpr Dictionary Dictionaries[] = {
    {"DICT_4X4_50", 50},       {"DICT_4X4_100", 100},       {"DICT_4X4_250", 250},         {"DICT_4X4_1000", 1000},
    {"DICT_5X5_50", 50},       {"DICT_5X5_100", 100},       {"DICT_5X5_250", 250},         {"DICT_5X5_1000", 1000},
    {"DICT_6X6_50", 50},       {"DICT_6X6_100", 100},       {"DICT_6X6_250", 250},         {"DICT_6X6_1000", 1000},
    {"DICT_7X7_50", 50},       {"DICT_7X7_100", 100},       {"DICT_7X7_250", 250},         {"DICT_7X7_1000", 1000},
    {"DICT_ARUCO_ORIGINAL", 1024}, {"DICT_APRILTAG_16h5", 30}, {"DICT_APRILTAG_25h9", 35},
    {"DICT_APRILTAG_36h10", 2320}, {"DICT_APRILTAG_36h11", 587},
};

} // namespace

int arucoDictionaryId(std::string_view name)
{
    for (int id = 0; id < int(std::size(Dictionaries)); ++id)
        if (Dictionaries[id].name == name)
            return id;
    return -1;
}

int arucoDictionarySize(std::string_view name)
{
    const int id = arucoDictionaryId(name);
    return id < 0 ? 0 : Dictionaries[id].markers;
}

int boardMarkerCount(const BoardSpec& board)
{
    switch (board.kind) {
    case BoardKind::Chessboard:
        return 0;
    case BoardKind::ArucoGrid:
        return board.columns * board.rows;
    case BoardKind::Charuco:
        return board.columns * board.rows / 2; // the white squares of a chessboard starting black
    }
    return 0;
}

Result<BoardSpec> parseBoard(std::string_view text)
{
    const std::vector<std::string_view> parts = split(text, ':');
    BoardSpec board;
    const std::string_view kind = parts.front();
    std::size_t next = 1;
    if (kind == "chessboard") {
        board.kind = BoardKind::Chessboard;
        if (parts.size() != 3)
            return wrong(text, "expected chessboard:COLUMNSxROWS:SQUARE (inner corners, square side in metres)");
    } else if (kind == "aruco-grid" || kind == "charuco") {
        board.kind = kind == "charuco" ? BoardKind::Charuco : BoardKind::ArucoGrid;
        const bool inverted = board.kind == BoardKind::Charuco && parts.size() == 6 && parts[5] == "inverted";
        if (parts.size() != 5 && !inverted)
            return wrong(text, board.kind == BoardKind::Charuco
                                   ? "expected charuco:DICTIONARY:COLUMNSxROWS:SQUARE:MARKER[:inverted]"
                                   : "expected aruco-grid:DICTIONARY:COLUMNSxROWS:MARKER:GAP");
        board.inverted = inverted;
        board.dictionary = std::string(parts[1]);
        if (arucoDictionaryId(board.dictionary) < 0)
            return wrong(text, quoted(board.dictionary) + " is not an ArUco dictionary (DICT_4X4_50, DICT_6X6_250, …)");
        next = 2;
    } else {
        return wrong(text, "unknown kind \"" + std::string(kind) + "\" (chessboard, aruco-grid or charuco)");
    }
    if (!gridSize(parts[next], board.columns, board.rows))
        return wrong(text, quoted(parts[next]) + " is not COLUMNSxROWS (e.g. 9x6)");
    if (!positiveLength(parts[next + 1], board.square))
        return wrong(text, quoted(parts[next + 1]) + " is not a positive length in metres");
    if (board.kind != BoardKind::Chessboard) {
        if (!positiveLength(parts[next + 2], board.second))
            return wrong(text, quoted(parts[next + 2]) + " is not a positive length in metres");
        if (board.kind == BoardKind::Charuco && board.second >= board.square)
            return wrong(text, "the markers must be smaller than the squares");
    }
    if (board.kind == BoardKind::Chessboard && (board.columns < 2 || board.rows < 2))
        return wrong(text, "a chessboard needs at least 2 × 2 inner corners");
    if (board.kind == BoardKind::Charuco && (board.columns < 2 || board.rows < 2))
        return wrong(text, "a ChArUco board needs at least 2 × 2 squares");
    if (const int size = arucoDictionarySize(board.dictionary); boardMarkerCount(board) > size && size > 0)
        return wrong(text, "the board needs " + std::to_string(boardMarkerCount(board)) + " markers but " +
                               board.dictionary + " has only " + std::to_string(size));
    return board;
}

std::string formatBoard(const BoardSpec& board)
{
    std::ostringstream out;
    out.precision(17);
    switch (board.kind) {
    case BoardKind::Chessboard:
        out << "chessboard:" << board.columns << 'x' << board.rows << ':' << board.square;
        break;
    case BoardKind::ArucoGrid:
        out << "aruco-grid:" << board.dictionary << ':' << board.columns << 'x' << board.rows << ':' << board.square
            << ':' << board.second;
        break;
    case BoardKind::Charuco:
        out << "charuco:" << board.dictionary << ':' << board.columns << 'x' << board.rows << ':' << board.square << ':'
            << board.second << (board.inverted ? ":inverted" : "");
        break;
    }
    return out.str();
}

std::vector<std::array<float, 3>> chessboardCorners(const BoardSpec& board)
{
    std::vector<std::array<float, 3>> corners;
    for (int y = 0; y < board.rows; ++y)
        for (int x = 0; x < board.columns; ++x)
            corners.push_back({float(x * board.square), float(y * board.square), 0.0f});
    return corners;
}

} // namespace thespis::core::ar
