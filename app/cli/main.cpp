// thespis-cli: the studio's work without a window (DESIGN.md, "Command line and farm").
//   thespis-cli validate SCENARIO
//   thespis-cli bake-motion SCENARIO --character NAME --out FILE.bvh [--fps N --start S --end S]
//   thespis-cli info SCENARIO
//   thespis-cli face-mapping MODEL.glb [--mapping FILE] [--save-mapping FILE]
// Every subcommand answers --help. Exit codes: exit_codes.h.

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "cancel.h"
#include "commands.h"
#include "exit_codes.h"

namespace {

using namespace thespis::cli;

void printMainHelp(std::FILE* out)
{
    std::fprintf(out, "Usage: thespis-cli COMMAND [arguments] [options]\n\n"
                      "Thespis Studio on the command line: check, inspect and bake scenarios.\n\nCommands:\n");
    for (const Command& command : commands())
        std::fprintf(out, "  %-13s %s\n", command.spec.name.c_str(), command.spec.summary.c_str());
    std::fprintf(out, "\nOptions:\n"
                      "  -h, --help     show this help and exit\n"
                      "  --version      show the version and exit\n\n"
                      "Run 'thespis-cli COMMAND --help' for a command's arguments.\n"
                      "Exit status: 0 success, 2 bad command line, 3 invalid input, 4 failure, 130 cancelled.\n");
}

const Command* findCommand(std::string_view name)
{
    for (const Command& command : commands())
        if (command.spec.name == name)
            return &command;
    return nullptr;
}

} // namespace

int main(int argc, char** argv)
{
    installInterruptHandlers();
    const std::vector<std::string_view> args(argv + 1, argv + argc);
    if (args.empty()) {
        printMainHelp(stderr);
        return ExitUsage;
    }
    const std::string_view first = args[0];
    if (first == "--help" || first == "-h") {
        printMainHelp(stdout);
        return ExitOk;
    }
    if (first == "--version") {
        std::printf("thespis-cli %s\n", THESPIS_VERSION);
        return ExitOk;
    }
    if (first == "help") {
        if (args.size() == 1) {
            printMainHelp(stdout);
            return ExitOk;
        }
        if (const Command* command = findCommand(args[1])) {
            std::fputs(helpText(command->spec).c_str(), stdout);
            return ExitOk;
        }
        std::fprintf(stderr, "thespis-cli: unknown command '%s'.\n\n", std::string(args[1]).c_str());
        printMainHelp(stderr);
        return ExitUsage;
    }

    const Command* command = findCommand(first);
    if (!command) {
        std::fprintf(stderr, "thespis-cli: unknown command '%s'.\n\n", std::string(first).c_str());
        printMainHelp(stderr);
        return ExitUsage;
    }
    const ParseOutcome parsed = parseArguments(command->spec, std::span(args).subspan(1));
    if (parsed.arguments.help) {
        std::fputs(helpText(command->spec).c_str(), stdout);
        return ExitOk;
    }
    if (!parsed.error.empty())
        return usageError(command->spec, parsed.error);
    const int code = command->run(command->spec, parsed.arguments);
    if (interrupted() && code != ExitOk)
        return ExitCancelled;
    return code;
}
