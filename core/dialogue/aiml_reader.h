#pragma once
// Reads AIML text into categories and their parsed templates (internal to core/dialogue).

#include <string>
#include <string_view>
#include <vector>

#include "dialogue/aiml.h"
#include "dialogue/template_tree.h"

namespace thespis::core::dialogue {

/// Categories and the templates they answer with; Category::templateIndex indexes `templates`.
struct CategoryStore {
    std::vector<Category> categories;
    std::vector<Template> templates;
};

/// Appends the categories of the AIML document `xml` (named `file` in messages) to `store`.
/// Problems (malformed XML with its line and column, a category without pattern or template)
/// go to `problems`; categories read before a fatal XML error are kept.
void readAiml(std::string_view xml, const std::string& file, CategoryStore& store,
              std::vector<LoadProblem>& problems);

} // namespace thespis::core::dialogue
