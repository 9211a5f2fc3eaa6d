// pybind11's embed header must come before anything that may include Qt (its `slots` macro).
#include <pybind11/embed.h>

#include "script_runner.h"

#include "runtime/interaction_service.h"
#include "runtime/voice_service.h"

#include "interpreter.h"

namespace thespis::script {

namespace py = pybind11;

namespace {

/// A file-like object whose write() hands text to the sink.
py::object writer(const OutputSink& sink, Stream stream)
{
    py::object types = py::module_::import("types");
    return types.attr("SimpleNamespace")(
        py::arg("write") = py::cpp_function([sink, stream](const std::string& text) {
            if (sink)
                sink(stream, text);
            return text.size();
        }),
        py::arg("flush") = py::cpp_function([] {}), py::arg("isatty") = py::cpp_function([] { return false; }));
}

/// "S.py, line 7: NameError: name 'x' is not defined" from a Python exception.
std::string describeException(py::error_already_set& error, const std::string& fileName)
{
    int line = 0;
    for (py::handle tb = error.trace(); tb && !tb.is_none(); tb = tb.attr("tb_next"))
        if (py::str(tb.attr("tb_frame").attr("f_code").attr("co_filename")).cast<std::string>() == fileName)
            line = tb.attr("tb_lineno").cast<int>();
    if (line == 0 && py::hasattr(error.value(), "lineno") && !error.value().attr("lineno").is_none())
        line = error.value().attr("lineno").cast<int>(); // a SyntaxError has no frame of the script
    const std::string type = py::str(error.type().attr("__name__"));
    const std::string what = py::str(error.value());
    return fileName + (line > 0 ? ", line " + std::to_string(line) : std::string()) + ": " + type +
           (what.empty() ? "" : ": " + what);
}

} // namespace

ScriptRunner::ScriptRunner() { ensurePython(); }

ScriptRunner::~ScriptRunner() { stop(); }

core::Result<void> ScriptRunner::run(const std::string& source, const std::string& fileName,
                                     std::shared_ptr<core::runtime::AnimationService> service, const OutputSink& sink,
                                     std::shared_ptr<core::runtime::SoundService> sound,
                                     std::shared_ptr<core::runtime::InteractionService> interaction)
{
    GilHolder gil;
    {
        const std::lock_guard lock(m_mutex);
        m_service = service;
        m_threadId = PyThread_get_thread_ident();
        m_stopping = false;
        m_running = true;
    }
    core::Result<void> result;
    py::module_ sys = py::module_::import("sys");
    py::object savedOut = sys.attr("stdout"), savedErr = sys.attr("stderr");
    try {
        sys.attr("stdout") = writer(sink, Stream::Out);
        sys.attr("stderr") = writer(sink, Stream::Err);
        py::module_ builtins = py::module_::import("builtins");
        py::dict globals;
        globals["__builtins__"] = builtins;
        globals["__name__"] = "__main__";
        globals["__file__"] = fileName;
        globals["thespis"] = py::module_::import("thespis");
        globals["animService"] = py::cast(service);
        globals["anim"] = globals["animService"];
        if (sound) {
            globals["voiceService"] = py::cast(std::make_shared<core::runtime::VoiceService>(service->sharedStage(), sound));
            globals["sndService"] = py::cast(sound);
            if (!interaction)
                interaction = std::make_shared<core::runtime::InteractionService>(service->sharedStage(), sound);
            globals["interactionService"] = py::cast(interaction);
        }
        py::object code = builtins.attr("compile")(source, fileName, "exec");
        builtins.attr("exec")(code, globals);
    } catch (py::error_already_set& error) {
        if (m_stopping && (error.matches(PyExc_KeyboardInterrupt))) {
            result = core::makeError(core::ErrorCode::Cancelled, fileName + " was stopped.");
        } else {
            const py::object lines = py::module_::import("traceback")
                                         .attr("format_exception")(error.type(), error.value(), error.trace());
            if (sink)
                sink(Stream::Err, py::str("").attr("join")(lines).cast<std::string>());
            result = core::makeError(core::ErrorCode::InvalidArgument, describeException(error, fileName));
        }
    }
    sys.attr("stdout") = savedOut;
    sys.attr("stderr") = savedErr;
    PyThreadState_SetAsyncExc(m_threadId, nullptr); // a stop that came too late must not hit the next script
    {
        const std::lock_guard lock(m_mutex);
        m_running = false;
        m_service.reset();
        m_threadId = 0;
    }
    return result;
}

void ScriptRunner::stop()
{
    unsigned long thread = 0;
    {
        const std::lock_guard lock(m_mutex);
        if (!m_running)
            return;
        m_stopping = true;
        if (m_service)
            m_service->requestStop(); // waits in C++ return at once
        thread = m_threadId;
    }
    // Python code gets KeyboardInterrupt at its next instruction. run() changes m_running and
    // the thread id only while it holds the GIL, so this is the same script.
    GilHolder gil;
    if (m_running && m_threadId == thread)
        PyThreadState_SetAsyncExc(thread, PyExc_KeyboardInterrupt);
}

std::string pythonVersion()
{
    ensurePython();
    GilHolder gil;
    return py::str(py::module_::import("platform").attr("python_version")());
}

} // namespace thespis::script
