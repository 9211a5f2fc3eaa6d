#pragma once
// What a bot can answer, as the listening grammar's source (paper §5.3: the recogniser listens
// only for what the dialogue can answer): every category's pattern in its literal form —
// reductions reached through <srai> included, for they are categories too — with AIML's
// wildcards as the grammar's, <set>s as their phrases and <bot name> as the property's words.

#include "dialogue/bot.h"
#include "dialogue/listening_grammar.h"
#include "speech/grammar_recogniser.h"
#include "util/error.h"

namespace thespis::core::dialogue {

/// The input the interaction service gives the bot when the recogniser did not understand: a
/// bot answers it with a category of that pattern ("Say that again?"). Never in a grammar.
inline constexpr std::string_view kNotUnderstood = "XNOTUNDERSTOOD";

/// The grammar source of `bot`: its patterns that say something (kNotUnderstood's and those of
/// wildcards alone left out, as those of categories skipped for a set the bot lacks), the sets they name,
/// and as the wildcards' vocabulary every word of its patterns.
GrammarSource grammarSourceOf(const Bot& bot);

/// A recogniser that listens for what `bot` can answer: the listening grammar of its patterns.
/// Errors as makeListeningGrammar()'s and GrammarRecogniser::open()'s.
Result<speech::GrammarRecogniser> listenFor(const Bot& bot, const ListeningOptions& listening = {},
                                            const speech::RecogniserOptions& recognising = {});

} // namespace thespis::core::dialogue
