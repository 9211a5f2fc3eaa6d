#include "target_options.h"

#include "commands.h"
#include "exit_codes.h"

namespace thespis::cli {

void addTargetOptions(CommandSpec& spec)
{
    spec.options.insert(spec.options.end(), {
        {"board", "SPEC", "aruco-grid:DICT:COLSxROWS:MARKER:GAP or charuco:DICT:COLSxROWS:SQUARE:MARKER[:inverted]"},
        {"target", "IMAGE", "a printed picture to track instead of a board (with --width)"},
        {"width", "METRES", "the printed picture's width"},
    });
}

int readTargetOptions(const CommandSpec& spec, const ParsedArguments& arguments, core::ar::TrackingTarget& out)
{
    if (const auto board = arguments.value("board")) {
        auto parsed = core::ar::parseBoard(*board);
        if (!parsed)
            return usageError(spec, parsed.error().message);
        out.board = *parsed;
    }
    if (const auto target = arguments.value("target")) {
        out.picture = *target;
        const auto width = arguments.value("width");
        const auto metres = width ? parseNumber(*width) : std::nullopt;
        if (!metres || !(*metres > 0))
            return usageError(spec, "--target needs --width, the picture's printed width in metres");
        out.pictureWidth = *metres;
    }
    if (out.board.has_value() == !out.picture.empty())
        return usageError(spec, "track either a board or a picture (--board or --target), one of the two");
    return ExitOk;
}

} // namespace thespis::cli
