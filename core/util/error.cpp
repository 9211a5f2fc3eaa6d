#include "util/error.h"

namespace thespis::core {

const char* errorCodeName(ErrorCode code)
{
    switch (code) {
    case ErrorCode::FileNotFound: return "file not found";
    case ErrorCode::NotOurFormat: return "not a supported format";
    case ErrorCode::CorruptData: return "corrupt data";
    case ErrorCode::NewerVersion: return "newer version";
    case ErrorCode::NotFound: return "not found";
    case ErrorCode::InvalidArgument: return "invalid argument";
    case ErrorCode::InvalidSchedule: return "invalid schedule";
    case ErrorCode::IoError: return "input/output error";
    case ErrorCode::Cancelled: return "cancelled";
    case ErrorCode::Internal: return "internal error";
    }
    return "error";
}

std::string describe(const Error& error)
{
    std::string text = std::string(errorCodeName(error.code)) + ": " + error.message;
    if (!error.detail.empty())
        text += " (" + error.detail + ")";
    return text;
}

} // namespace thespis::core
