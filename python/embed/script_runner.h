#pragma once
// ScriptRunner: runs the paper's Python scripts (§4.5) inside the studio and `thespis-cli run`,
// with the same `thespis` module python3 imports built in. A script sees `animService` (also
// `anim`): the AnimationService of the stage it plays on, `voiceService` (also `sndService`):
// the sound service on the same clock, when one is given, `interactionService` (a character
// conversing, on the same stage and clock) and `thespis`. Its output goes to a
// sink (the studio's console, the terminal); an exception ends it with its traceback written
// there and an error naming the file and line. stop(), from any thread, ends a running script:
// its waits return at once and Python code gets KeyboardInterrupt.
//
// Python is started once per process, the first time a runner is made, and the GIL is released
// so that any thread may run scripts (one at a time per runner).

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include "runtime/animation_service.h"
#include "runtime/interaction_service.h"
#include "runtime/sound.h"
#include "util/error.h"

namespace thespis::script {

enum class Stream { Out, Err };
using OutputSink = std::function<void(Stream stream, std::string_view text)>;

class ScriptRunner {
public:
    ScriptRunner();
    ~ScriptRunner();
    ScriptRunner(const ScriptRunner&) = delete;
    ScriptRunner& operator=(const ScriptRunner&) = delete;

    /// Runs `source` to its end in the calling thread. `fileName` names it in tracebacks.
    /// Errors: the script raised (message "S.py, line N: NameError: …"), or was stopped
    /// (Cancelled).
    /// With `sound`, the script gets voiceService, sndService and interactionService: the one
    /// given (the studio's, whose Conversation dock goes on with whom a script handed over),
    /// else one of its own.
    core::Result<void> run(const std::string& source, const std::string& fileName,
                           std::shared_ptr<core::runtime::AnimationService> service, const OutputSink& sink,
                           std::shared_ptr<core::runtime::SoundService> sound = nullptr,
                           std::shared_ptr<core::runtime::InteractionService> interaction = nullptr);
    /// Ends the script running in run(), if any (any thread).
    void stop();
    bool isRunning() const { return m_running; }

private:
    std::mutex m_mutex; // guards the service and thread id while a script starts or stops
    std::shared_ptr<core::runtime::AnimationService> m_service;
    unsigned long m_threadId = 0;
    std::atomic<bool> m_running = false, m_stopping = false;
};

/// The Python version the program embeds ("3.11.2"); starts Python if needed.
std::string pythonVersion();

} // namespace thespis::script
