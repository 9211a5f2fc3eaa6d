#include "errors.h"

#include <Python.h>

namespace thespis::python {
namespace {

using core::ErrorCode;

// Exception types created once at import; kept for the life of the interpreter (module
// objects are never unloaded), so they are deliberately never released.
PyObject* g_formatError = nullptr;
PyObject* g_cancelled = nullptr;

PyObject* exceptionType(ErrorCode code)
{
    switch (code) {
    case ErrorCode::FileNotFound: return PyExc_FileNotFoundError;
    case ErrorCode::NotOurFormat:
    case ErrorCode::CorruptData:
    case ErrorCode::NewerVersion: return g_formatError;
    case ErrorCode::NotFound: return PyExc_KeyError;
    case ErrorCode::InvalidArgument:
    case ErrorCode::InvalidSchedule: return PyExc_ValueError;
    case ErrorCode::IoError: return PyExc_OSError;
    case ErrorCode::Cancelled: return g_cancelled;
    case ErrorCode::Internal: return PyExc_RuntimeError;
    }
    return PyExc_RuntimeError;
}

} // namespace

void throwError(const core::Error& error)
{
    PyObject* type = exceptionType(error.code);
    // The message is what the user reads in a traceback; the detail (technical context) is
    // appended there too, and also kept apart as an attribute for programs.
    std::string text = error.message;
    if (!error.detail.empty())
        text += " (" + error.detail + ")";
    py::object instance = py::reinterpret_borrow<py::object>(type)(text);
    instance.attr("code") = py::cast(error.code);
    instance.attr("detail") = error.detail;
    PyErr_SetObject(type, instance.ptr());
    throw py::error_already_set();
}

void bindErrors(py::module_& m)
{
    py::enum_<ErrorCode>(m, "ErrorCode", "Why a core operation failed (the `code` of every thespis exception).")
        .value("file_not_found", ErrorCode::FileNotFound)
        .value("not_our_format", ErrorCode::NotOurFormat)
        .value("corrupt_data", ErrorCode::CorruptData)
        .value("newer_version", ErrorCode::NewerVersion)
        .value("not_found", ErrorCode::NotFound)
        .value("invalid_argument", ErrorCode::InvalidArgument)
        .value("invalid_schedule", ErrorCode::InvalidSchedule)
        .value("io_error", ErrorCode::IoError)
        .value("cancelled", ErrorCode::Cancelled)
        .value("internal", ErrorCode::Internal);

    py::class_<core::Error>(m, "Error", "A problem reported as a value (e.g. by validate_scenario).")
        .def_readonly("code", &core::Error::code)
        .def_readonly("message", &core::Error::message)
        .def_readonly("detail", &core::Error::detail)
        .def("__str__", [](const core::Error& e) { return core::describe(e); })
        .def("__repr__", [](const core::Error& e) {
            return "<thespis.Error " + std::string(core::errorCodeName(e.code)) + ": " + e.message + ">";
        });

    g_formatError = PyErr_NewExceptionWithDoc(
        "thespis.FormatError",
        "A file is not in the expected format, is malformed (the message names the line or field), "
        "or was written by a newer Thespis.",
        PyExc_ValueError, nullptr);
    g_cancelled = PyErr_NewExceptionWithDoc("thespis.Cancelled", "The operation was cancelled.",
                                            PyExc_KeyboardInterrupt, nullptr);
    if (!g_formatError || !g_cancelled)
        throw py::error_already_set();
    m.attr("FormatError") = py::reinterpret_borrow<py::object>(g_formatError);
    m.attr("Cancelled") = py::reinterpret_borrow<py::object>(g_cancelled);
}

} // namespace thespis::python
