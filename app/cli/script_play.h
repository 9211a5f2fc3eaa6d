#pragma once
// The Python script `run` and `play` play along their renders (core::runtime::playScript): the
// paper's animService on the host's stage and clock, its prints straight to the terminal.

#include "runtime/scripted_play.h"
#include "script_runner.h"
#include "script_source.h"

namespace thespis::cli {

/// `source` run on `runner`, which must outlive the returned script.
core::runtime::PlayScript playAlong(script::ScriptRunner& runner, const ScriptSource& source);

} // namespace thespis::cli
