#include "speech/bml.h"

#include <expat.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

#include "util/text.h"

namespace thespis::core::speech {
namespace {

constexpr std::string_view kBmlNamespace = "http://www.bml-initiative.org/bml/bml-1.0";
// Bounds that keep a hostile block cheap to read: a block is a few kilobytes, and only the
// ignored <description> content nests at all.
constexpr std::size_t kMaxInputBytes = std::size_t(4) << 20;
constexpr std::size_t kMaxDepth = 32;

constexpr std::array<std::string_view, kBmlPointCount> kPointNames = {"start",     "ready", "strokeStart", "stroke",
                                                                     "strokeEnd", "relax", "end"};
constexpr std::array<std::string_view, 7> kKindNames = {"speech", "gesture",  "faceLexeme", "head",
                                                        "gaze",   "pointing", "wait"};
constexpr std::array<std::string_view, 3> kCompositionNames = {"MERGE", "APPEND", "REPLACE"};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// A whole string (spaces around allowed) as a finite number, read the same in every locale.
std::optional<double> finiteNumber(std::string_view text)
{
    text = trimmed(text);
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

// The shortest text that reads back to the same double.
std::string numberString(double value)
{
    char buffer[32];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, written.ptr);
}

// An id a sync reference can name: "s1:t1" splits at colons and ends the point at a space or sign.
bool isReferable(std::string_view id)
{
    return !id.empty() && std::none_of(id.begin(), id.end(), [](char c) { return isSpace(c) || c == ':'; });
}

struct SyncRefText {
    BmlSyncRef ref;
    std::string_view block; ///< the "bml1" of "bml1:s1:start"; empty when not given
};

// Reads a sync attribute's value, or says in `problem` what is wrong with it.
std::optional<SyncRefText> readSyncRef(std::string_view text, std::string& problem)
{
    text = trimmed(text);
    const std::size_t lastColon = text.rfind(':');
    if (lastColon == std::string_view::npos) {
        if (const auto seconds = finiteNumber(text))
            return SyncRefText{BmlSyncRef{{}, {}, *seconds}, {}};
        problem = "it is neither a number of seconds nor a reference such as \"s1:start + 0.5\"";
        return std::nullopt;
    }
    // Ids may hold "-" before the last colon; after it, the point's name ends at a space or a sign.
    const std::size_t pointEnd = std::min(text.find_first_of(" \t\n\r+-", lastColon + 1), text.size());
    const std::string_view point = text.substr(lastColon + 1, pointEnd - lastColon - 1);
    const std::string_view rest = trimmed(text.substr(pointEnd));
    double offset = 0;
    if (!rest.empty()) {
        const std::string_view magnitude = trimmed(rest.substr(1));
        const bool signedOnce = (rest[0] == '+' || rest[0] == '-') && !magnitude.starts_with('-');
        const auto seconds = signedOnce ? finiteNumber(magnitude) : std::nullopt;
        if (!seconds) {
            problem = "after " + inQuotes(text.substr(0, pointEnd)) + " comes " + inQuotes(rest)
                      + " where \"+ seconds\" or \"- seconds\" was expected";
            return std::nullopt;
        }
        offset = rest[0] == '-' ? -*seconds : *seconds;
    }
    // "behaviour:point" or "block:behaviour:point".
    std::string_view behavior = text.substr(0, lastColon), block;
    const std::size_t colon = behavior.find(':');
    if (colon != std::string_view::npos) {
        block = behavior.substr(0, colon);
        behavior = behavior.substr(colon + 1);
    }
    if (behavior.find(':') != std::string_view::npos) {
        problem = "it has more than three parts";
        return std::nullopt;
    }
    if (!isReferable(behavior) || point.empty() || (colon != std::string_view::npos && !isReferable(block))) {
        problem = "it has an empty id or a space in one";
        return std::nullopt;
    }
    return SyncRefText{BmlSyncRef{std::string(behavior), std::string(point), offset}, block};
}

struct ParseError {
    int line, column;
    std::string message;
};

// One start tag: its local name (any "prefix:" taken off) and its attributes.
struct Element {
    std::string_view name;
    const XML_Char** attributes;
    int line, column;

    std::optional<std::string_view> attribute(std::string_view key) const
    {
        for (const XML_Char** a = attributes; *a; a += 2)
            if (key == a[0])
                return std::string_view(a[1]);
        return std::nullopt;
    }
    [[noreturn]] void fail(std::string message) const { throw ParseError{line, column, std::move(message)}; }
};

std::string_view localName(std::string_view name)
{
    const std::size_t colon = name.rfind(':');
    return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

// An attribute the behaviour `what` ("<gaze> "z1"") cannot do without.
std::string requiredAttribute(const Element& e, const std::string& what, std::string_view key)
{
    std::string value(e.attribute(key).value_or(""));
    if (value.empty())
        e.fail(what + " needs a " + std::string(key));
    return value;
}

struct NumberRule {
    double least, most;
    bool whole;
    std::string_view says;
};
constexpr double kUnbounded = std::numeric_limits<double>::infinity();
constexpr NumberRule kFraction{0, 1, false, "a number from 0 to 1"};
constexpr NumberRule kRepetitions{1, 1e6, true, "a whole number from 1 to 1000000"};
constexpr NumberRule kDegrees{-kUnbounded, kUnbounded, false, "a number of degrees"};
constexpr NumberRule kSeconds{0, kUnbounded, false, "a number of seconds, not negative"};

double numberAttribute(const Element& e, const std::string& what, std::string_view key, double fallback,
                       const NumberRule& rule)
{
    const auto text = e.attribute(key);
    if (!text)
        return fallback;
    const auto value = finiteNumber(*text);
    if (!value || *value < rule.least || *value > rule.most || (rule.whole && *value != std::floor(*value)))
        e.fail("the " + std::string(key) + " of " + what + " must be " + std::string(rule.says) + ", not "
               + inQuotes(*text));
    return *value;
}

std::string optionalAttribute(const Element& e, std::string_view key)
{
    return std::string(e.attribute(key).value_or(""));
}

// What only some kinds of behaviour have: lexeme, amount, target …
void readOwnAttributes(const Element& e, const std::string& what, BmlBehavior& b)
{
    switch (b.kind) {
    case BmlBehaviorKind::Speech: break;
    case BmlBehaviorKind::Gesture:
        if (e.attribute("lexeme") && e.attribute("name"))
            e.fail(what + " has both a lexeme and a name: give one");
        b.byName = !e.attribute("lexeme") && e.attribute("name");
        b.lexeme = requiredAttribute(e, what, b.byName ? "name" : "lexeme");
        break;
    case BmlBehaviorKind::FaceLexeme:
        b.lexeme = requiredAttribute(e, what, "lexeme");
        b.amount = numberAttribute(e, what, "amount", 1, kFraction);
        break;
    case BmlBehaviorKind::Head:
        b.lexeme = requiredAttribute(e, what, "lexeme");
        b.amount = numberAttribute(e, what, "amount", 1, kFraction);
        b.repetition = int(numberAttribute(e, what, "repetition", 1, kRepetitions));
        break;
    case BmlBehaviorKind::Gaze:
        b.target = requiredAttribute(e, what, "target");
        b.influence = optionalAttribute(e, "influence");
        b.offsetAngle = numberAttribute(e, what, "offsetAngle", 0, kDegrees);
        b.offsetDirection = optionalAttribute(e, "offsetDirection");
        break;
    case BmlBehaviorKind::Pointing:
        b.target = requiredAttribute(e, what, "target");
        b.mode = optionalAttribute(e, "mode");
        break;
    case BmlBehaviorKind::Wait: b.duration = numberAttribute(e, what, "duration", 0, kSeconds); break;
    }
}

// Builds the block from expat's events. Handlers never let an exception into expat (a C library):
// each catches the ParseError, keeps it and stops the parser.
class BlockReader {
public:
    explicit BlockReader(XML_Parser parser) : m_parser(parser) {}

    BmlBlock block;
    std::optional<ParseError> error;

    static void XMLCALL onStart(void* self, const XML_Char* name, const XML_Char** attributes)
    {
        static_cast<BlockReader*>(self)->guarded([&](BlockReader& r) { r.start(name, attributes); });
    }
    static void XMLCALL onEnd(void* self, const XML_Char*)
    {
        static_cast<BlockReader*>(self)->guarded([](BlockReader& r) { r.end(); });
    }
    static void XMLCALL onCharacters(void* self, const XML_Char* text, int length)
    {
        static_cast<BlockReader*>(self)->guarded(
            [&](BlockReader& r) { r.characters(std::string_view(text, std::size_t(length))); });
    }
    static void XMLCALL onDoctype(void* self, const XML_Char*, const XML_Char*, const XML_Char*, int)
    {
        // No DTD: nothing in BML needs one, and its entities are how XML documents blow up.
        static_cast<BlockReader*>(self)->guarded([](BlockReader& r) { r.here().fail("BML has no DOCTYPE"); });
    }

private:
    // Where the reader is; Ignored is a <description> and everything in it.
    enum class Context { Block, Behavior, Speech, Text, Sync, Ignored };

    template <class F>
    void guarded(F&& handle)
    {
        if (error)
            return;
        try {
            handle(*this);
        } catch (const ParseError& e) {
            error = e;
            XML_StopParser(m_parser, XML_FALSE);
        }
    }

    Element here(std::string_view name = {}, const XML_Char** attributes = nullptr) const
    {
        // expat counts columns from 0, in characters; messages count from 1.
        return Element{name, attributes, int(XML_GetCurrentLineNumber(m_parser)),
                       int(XML_GetCurrentColumnNumber(m_parser)) + 1};
    }

    void start(const XML_Char* rawName, const XML_Char** attributes)
    {
        const Element e = here(localName(rawName), attributes);
        if (m_open.size() >= kMaxDepth)
            e.fail("elements are nested more than " + std::to_string(kMaxDepth) + " deep");
        const std::optional<Context> parent = m_open.empty() ? std::nullopt : std::optional(m_open.back());
        if (!parent) {
            if (e.name != "bml")
                e.fail("the root element is <" + std::string(e.name) + ">, not <bml>: this is not a BML block");
            readBlock(e);
            m_open.push_back(Context::Block);
        } else if (*parent == Context::Ignored || e.name == "description") {
            if (*parent == Context::Block || *parent == Context::Text || *parent == Context::Sync)
                e.fail("<description> belongs in a behaviour, not in <" + std::string(openName()) + ">");
            m_open.push_back(Context::Ignored);
        } else if (*parent == Context::Block) {
            readBehavior(e);
            m_open.push_back(block.behaviors.back().kind == BmlBehaviorKind::Speech ? Context::Speech
                                                                                    : Context::Behavior);
        } else if (*parent == Context::Speech && e.name == "text") {
            if (m_speechHasText)
                e.fail("<speech> " + inQuotes(block.behaviors.back().id) + " has a second <text>");
            m_speechHasText = true;
            m_pendingSpace = false;
            m_open.push_back(Context::Text);
        } else if (e.name == "sync" && *parent == Context::Text) {
            readSyncMark(e);
            m_open.push_back(Context::Sync);
        } else if (e.name == "sync" && *parent == Context::Speech) {
            e.fail("<sync> must be inside the speech's <text>");
        } else {
            e.fail("unknown element <" + std::string(e.name) + "> in <" + std::string(openName()) + ">");
        }
    }

    void end()
    {
        const Context closed = m_open.back();
        m_open.pop_back();
        BmlBehavior* speech = block.behaviors.empty() ? nullptr : &block.behaviors.back();
        if (closed == Context::Text) {
            // A mark before trailing spaces was counted past the space that never came.
            for (auto& [id, offset] : speech->syncMarks)
                offset = std::min(offset, speech->text.size());
        } else if (closed == Context::Speech && !m_speechHasText) {
            throw ParseError{speech->line, speech->column, "<speech> " + inQuotes(speech->id) + " needs a <text>"};
        }
    }

    void characters(std::string_view text)
    {
        const Context context = m_open.empty() ? Context::Ignored : m_open.back();
        if (context == Context::Ignored)
            return;
        if (context == Context::Text) {
            // Runs of white space read as one space, and none at either end.
            std::string& spoken = block.behaviors.back().text;
            for (char c : text) {
                if (isSpace(c)) {
                    m_pendingSpace = !spoken.empty();
                    continue;
                }
                if (m_pendingSpace)
                    spoken += ' ';
                m_pendingSpace = false;
                spoken += c;
            }
            return;
        }
        const auto printable = std::find_if_not(text.begin(), text.end(), isSpace);
        if (printable == text.end())
            return;
        // Point at the first printable character, not at the white space before it.
        Element e = here();
        for (auto c = text.begin(); c != printable; ++c) {
            if (*c == '\n') {
                ++e.line;
                e.column = 1;
            } else {
                ++e.column;
            }
        }
        e.fail(context == Context::Sync ? "<sync> must be empty"
                                        : "text outside a speech's <text>, in <" + std::string(openName()) + ">");
    }

    std::string_view openName() const
    {
        switch (m_open.back()) {
        case Context::Block: return "bml";
        case Context::Text: return "text";
        case Context::Sync: return "sync";
        case Context::Ignored: return "description";
        case Context::Behavior:
        case Context::Speech: break;
        }
        return bmlKindName(block.behaviors.back().kind);
    }

    void readBlock(const Element& e)
    {
        block.id = optionalAttribute(e, "id");
        if (block.id.empty())
            e.fail("<bml> needs an id");
        if (!isReferable(block.id))
            e.fail("the block's id " + inQuotes(block.id) + " has a space or a \":\", so nothing can refer to it");
        block.character = optionalAttribute(e, "characterId");
        if (const auto composition = e.attribute("composition")) {
            const std::string wanted = lowercase(trimmed(*composition));
            const auto it = std::find_if(kCompositionNames.begin(), kCompositionNames.end(),
                                         [&](std::string_view name) { return lowercase(name) == wanted; });
            if (it == kCompositionNames.end())
                e.fail("the composition " + inQuotes(*composition) + " is not MERGE, APPEND or REPLACE");
            block.composition = BmlComposition(it - kCompositionNames.begin());
        }
    }

    void readBehavior(const Element& e)
    {
        const auto kind = std::find(kKindNames.begin(), kKindNames.end(), e.name);
        if (kind == kKindNames.end())
            e.fail("unknown element <" + std::string(e.name)
                   + "> in <bml>: expected speech, gesture, faceLexeme, head, gaze, pointing or wait");
        BmlBehavior b;
        b.kind = BmlBehaviorKind(kind - kKindNames.begin());
        b.line = e.line;
        b.column = e.column;
        b.id = optionalAttribute(e, "id");
        const std::string what = "<" + std::string(e.name) + "> " + inQuotes(b.id);
        if (b.id.empty())
            e.fail("<" + std::string(e.name) + "> needs an id");
        if (!isReferable(b.id))
            e.fail("the id of " + what + " has a space or a \":\", so nothing can refer to it");
        if (!m_ids.insert(b.id).second)
            e.fail("the id " + inQuotes(b.id) + " is used twice in the block");
        for (int p = 0; p < kBmlPointCount; ++p)
            if (const auto value = e.attribute(kPointNames[p]))
                b.sync[BmlPoint(p)] = syncRef(e, what, kPointNames[p], *value);

        if (b.kind == BmlBehaviorKind::Speech) {
            m_speechHasText = false;
            m_markIds.clear();
        }
        readOwnAttributes(e, what, b);
        block.behaviors.push_back(std::move(b));
    }

    BmlSyncRef syncRef(const Element& e, const std::string& what, std::string_view point, std::string_view value) const
    {
        std::string problem;
        auto read = readSyncRef(value, problem);
        if (!read)
            e.fail("the " + std::string(point) + " " + inQuotes(value) + " of " + what + " is not a sync reference: "
                   + problem);
        if (!read->block.empty() && read->block != block.id)
            e.fail("the " + std::string(point) + " of " + what + " refers to the block " + inQuotes(read->block)
                   + ": only this block, " + inQuotes(block.id) + ", can be referred to");
        return std::move(read->ref);
    }

    void readSyncMark(const Element& e)
    {
        BmlBehavior& speech = block.behaviors.back();
        const std::string id = optionalAttribute(e, "id");
        if (id.empty())
            e.fail("<sync> needs an id");
        // "s1:t-1" reads as t minus one: a mark's id must read back as a point's name.
        if (!isReferable(id) || id.find_first_of("+-") != std::string::npos)
            e.fail("the <sync> id " + inQuotes(id) + " has a space, \":\", \"+\" or \"-\", so nothing can refer to it");
        if (bmlPointNamed(id))
            e.fail("the <sync> id " + inQuotes(id) + " is the name of a standard sync point");
        if (!m_markIds.insert(id).second)
            e.fail("the <sync> id " + inQuotes(id) + " is used twice in <speech> " + inQuotes(speech.id));
        // White space just read becomes one space before the next word: the mark stands at the word.
        speech.syncMarks.emplace_back(id, speech.text.size() + (m_pendingSpace ? 1 : 0));
    }

    XML_Parser m_parser;
    std::vector<Context> m_open;
    std::set<std::string, std::less<>> m_ids;     ///< of the block's behaviours
    std::set<std::string, std::less<>> m_markIds; ///< of the current speech's <sync> marks
    bool m_speechHasText = false;
    bool m_pendingSpace = false; ///< white space read in a <text> since its last printable character
};

std::string escaped(std::string_view text)
{
    std::string out;
    for (char c : text) {
        switch (c) {
        // Attribute values read these as spaces unless written as references.
        case '\t': out += "&#9;"; break;
        case '\n': out += "&#10;"; break;
        case '\r': out += "&#13;"; break;
        default: appendEscaped(out, c, true);
        }
    }
    return out;
}

void writeAttribute(std::string& out, std::string_view key, std::string_view value)
{
    out += ' ';
    out += key;
    out += "=\"";
    out += escaped(value);
    out += '"';
}

void writeSpeechText(std::string& out, const BmlBehavior& speech)
{
    // Marks in text order (as read); those at one offset keep their order.
    std::vector<std::pair<std::string, std::size_t>> marks = speech.syncMarks;
    std::stable_sort(marks.begin(), marks.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    out += "<text>";
    std::size_t written = 0;
    for (const auto& [id, offset] : marks) {
        const std::size_t at = std::clamp(offset, written, speech.text.size());
        out += escaped(std::string_view(speech.text).substr(written, at - written));
        written = at;
        out += "<sync";
        writeAttribute(out, "id", id);
        out += "/>";
    }
    out += escaped(std::string_view(speech.text).substr(written));
    out += "</text>";
}

void writeBehavior(std::string& out, const BmlBehavior& b)
{
    out += "  <";
    out += bmlKindName(b.kind);
    writeAttribute(out, "id", b.id);
    for (const auto& [point, ref] : b.sync)
        writeAttribute(out, bmlPointName(point), bmlSyncRefString(ref));
    // Values equal to the reader's defaults are left out.
    switch (b.kind) {
    case BmlBehaviorKind::Speech: break;
    case BmlBehaviorKind::Gesture: writeAttribute(out, b.byName ? "name" : "lexeme", b.lexeme); break;
    case BmlBehaviorKind::FaceLexeme:
    case BmlBehaviorKind::Head:
        writeAttribute(out, "lexeme", b.lexeme);
        if (b.amount != 1)
            writeAttribute(out, "amount", numberString(b.amount));
        if (b.kind == BmlBehaviorKind::Head && b.repetition != 1)
            writeAttribute(out, "repetition", std::to_string(b.repetition));
        break;
    case BmlBehaviorKind::Gaze:
        writeAttribute(out, "target", b.target);
        if (!b.influence.empty())
            writeAttribute(out, "influence", b.influence);
        if (b.offsetAngle != 0)
            writeAttribute(out, "offsetAngle", numberString(b.offsetAngle));
        if (!b.offsetDirection.empty())
            writeAttribute(out, "offsetDirection", b.offsetDirection);
        break;
    case BmlBehaviorKind::Pointing:
        writeAttribute(out, "target", b.target);
        if (!b.mode.empty())
            writeAttribute(out, "mode", b.mode);
        break;
    case BmlBehaviorKind::Wait:
        if (b.duration != 0)
            writeAttribute(out, "duration", numberString(b.duration));
        break;
    }
    if (b.kind == BmlBehaviorKind::Speech) {
        out += '>';
        writeSpeechText(out, b);
        out += "</speech>\n";
    } else {
        out += "/>\n";
    }
}

} // namespace

std::string_view bmlPointName(BmlPoint point) { return kPointNames[std::size_t(point)]; }

std::optional<BmlPoint> bmlPointNamed(std::string_view name)
{
    const auto it = std::find(kPointNames.begin(), kPointNames.end(), name);
    return it == kPointNames.end() ? std::nullopt : std::optional(BmlPoint(it - kPointNames.begin()));
}

std::string_view bmlKindName(BmlBehaviorKind kind) { return kKindNames[std::size_t(kind)]; }

Result<BmlSyncRef> parseBmlSyncRef(std::string_view text)
{
    std::string problem;
    auto read = readSyncRef(text, problem);
    if (!read)
        return makeError(ErrorCode::InvalidArgument, inQuotes(text) + " is not a sync reference: " + problem + ".");
    return std::move(read->ref);
}

std::string bmlSyncRefString(const BmlSyncRef& ref)
{
    if (ref.behavior.empty())
        return numberString(ref.offset);
    std::string out = ref.behavior + ":" + ref.point;
    if (ref.offset > 0)
        out += " + " + numberString(ref.offset);
    else if (ref.offset < 0)
        out += " - " + numberString(-ref.offset);
    return out;
}

Result<BmlBlock> parseBml(std::string_view xml)
{
    if (xml.size() > kMaxInputBytes)
        return makeError(ErrorCode::CorruptData, "line 1, column 1: the block is larger than "
                                                     + std::to_string(kMaxInputBytes >> 20) + " MiB.");
    const std::unique_ptr<std::remove_pointer_t<XML_Parser>, decltype(&XML_ParserFree)> parser(
        XML_ParserCreate(nullptr), &XML_ParserFree);
    if (!parser)
        return makeError(ErrorCode::Internal, "line 1, column 1: the XML reader could not start.");
    BlockReader reader(parser.get());
    XML_SetUserData(parser.get(), &reader);
    XML_SetElementHandler(parser.get(), &BlockReader::onStart, &BlockReader::onEnd);
    XML_SetCharacterDataHandler(parser.get(), &BlockReader::onCharacters);
    XML_SetStartDoctypeDeclHandler(parser.get(), &BlockReader::onDoctype);
    const bool parsed = XML_Parse(parser.get(), xml.data(), int(xml.size()), XML_TRUE) == XML_STATUS_OK;
    if (reader.error)
        return makeError(ErrorCode::CorruptData, "line " + std::to_string(reader.error->line) + ", column "
                                                     + std::to_string(reader.error->column) + ": "
                                                     + reader.error->message + ".");
    if (!parsed)
        return makeError(ErrorCode::CorruptData,
                         "line " + std::to_string(XML_GetCurrentLineNumber(parser.get())) + ", column "
                             + std::to_string(XML_GetCurrentColumnNumber(parser.get()) + 1)
                             + ": the XML is malformed: " + XML_ErrorString(XML_GetErrorCode(parser.get())) + ".");
    return std::move(reader.block);
}

std::string bmlString(const BmlBlock& block)
{
    std::string out = "<bml";
    writeAttribute(out, "xmlns", kBmlNamespace);
    writeAttribute(out, "id", block.id);
    if (!block.character.empty())
        writeAttribute(out, "characterId", block.character);
    writeAttribute(out, "composition", kCompositionNames[std::size_t(block.composition)]);
    out += ">\n";
    for (const BmlBehavior& b : block.behaviors)
        writeBehavior(out, b);
    out += "</bml>\n";
    return out;
}

} // namespace thespis::core::speech
