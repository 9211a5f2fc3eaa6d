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

} // namespace

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
        if (!board.dictionary.starts_with("DICT_"))
            return wrong(text, "\"" + board.dictionary + "\" is not an ArUco dictionary (DICT_4X4_50, DICT_6X6_250, …)");
        next = 2;
    } else {
        return wrong(text, "unknown kind \"" + std::string(kind) + "\" (chessboard, aruco-grid or charuco)");
    }
    if (!gridSize(parts[next], board.columns, board.rows))
        return wrong(text, "\"" + std::string(parts[next]) + "\" is not COLUMNSxROWS (e.g. 9x6)");
    if (!positiveLength(parts[next + 1], board.square))
        return wrong(text, "\"" + std::string(parts[next + 1]) + "\" is not a positive length in metres");
    if (board.kind != BoardKind::Chessboard) {
        if (!positiveLength(parts[next + 2], board.second))
            return wrong(text, "\"" + std::string(parts[next + 2]) + "\" is not a positive length in metres");
        if (board.kind == BoardKind::Charuco && board.second >= board.square)
            return wrong(text, "the markers must be smaller than the squares");
    }
    if (board.kind == BoardKind::Chessboard && (board.columns < 2 || board.rows < 2))
        return wrong(text, "a chessboard needs at least 2 × 2 inner corners");
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
