#include "script_play.h"

#include <cstdio>

#include "runtime/animation_service.h"

namespace thespis::cli {

core::runtime::PlayScript playAlong(script::ScriptRunner& runner, const ScriptSource& source)
{
    return {[&runner, source](const core::runtime::ScriptHost& host) {
                auto service = std::make_shared<core::runtime::AnimationService>(host.stage, host.clock);
                // Unbuffered, so that the script's prints show as they happen, between progress
                // lines and through a pipe.
                const auto sink = [](script::Stream stream, std::string_view text) {
                    std::FILE* out = stream == script::Stream::Out ? stdout : stderr;
                    std::fwrite(text.data(), 1, text.size(), out);
                    std::fflush(out);
                };
                return runner.run(source.text, source.fileName, service, sink, host.sound);
            },
            [&runner] { runner.stop(); }};
}

} // namespace thespis::cli
