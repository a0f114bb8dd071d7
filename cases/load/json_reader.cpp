#include "lexel/cases/load/json_reader.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <mutex>
#include <new>
#include <optional>
#include <set>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include "lexel/cases/load/memory_budget.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/allocation_cap.h"

namespace lexel::cases {

namespace {

std::string TypeName(const nlohmann::json& v) {
    if (v.is_number_integer() || v.is_number_unsigned()) return "an integer";
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_boolean()) return "a boolean";
    if (v.is_array()) return "an array";
    if (v.is_object()) return "an object";
    return "null";
}

// Control characters written as JSON writes them ("\n", "\u0001"), so that a message quoting a
// key or a value of the case stays on one line (a key "a\nb" made two, found by
// tests/fuzz/flatland_case_fuzzer: tests/fuzz/seeds/flatland/regress_newline_key.json).
std::string Printable(std::string_view text) {
    std::string out;
    for (char c : text) {
        const auto code = static_cast<unsigned char>(c);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (code < 0x20 || code == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", code);
            out += escaped;
        } else {
            out += c;
        }
    }
    return out;
}

// JSON pointer escaping (RFC 6901): '~' → "~0", '/' → "~1"; then Printable.
std::string EscapeKey(std::string_view key) {
    std::string out;
    for (char c : key) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return Printable(out);
}

}  // namespace

std::string FormatNumber(double value) {
    std::ostringstream out;
    out.precision(15);
    out << value;
    return out.str();
}

namespace {

// Refuses a repeated key in any object (nlohmann keeps the last silently), naming its JSON pointer.
// Tracks the pointer of the value being parsed: per open object its last key, per open array the
// number of elements begun.
class DuplicateKeyCheck {
  public:
    explicit DuplicateKeyCheck(const std::string& sourceName) : sourceName_(sourceName) {}

    bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        switch (event) {
            case Event::object_start:
            case Event::array_start:
                BeginElement();
                frames_.push_back({event == Event::array_start, 0, {}, {}});
                break;
            case Event::object_end:
            case Event::array_end:
                frames_.pop_back();
                break;
            case Event::key: {
                Frame& object = frames_.back();
                const std::string key = parsed.get<std::string>();
                if (!object.keys.insert(key).second)
                    throw InputError(sourceName_ + ": " + Pointer() + "/" + EscapeKey(key) +
                                     ": duplicate key (each key may appear once)");
                object.key = key;
                break;
            }
            case Event::value:
                BeginElement();
                break;
        }
        return true;
    }

  private:
    struct Frame {
        bool array;
        std::size_t elements;
        std::set<std::string> keys;
        std::string key;
    };

    void BeginElement() {
        if (!frames_.empty() && frames_.back().array) ++frames_.back().elements;
    }
    // The pointer of the innermost open object or array.
    std::string Pointer() const {
        std::string pointer;
        for (std::size_t i = 0; i + 1 < frames_.size(); ++i)
            pointer += "/" + (frames_[i].array ? std::to_string(frames_[i].elements - 1)
                                               : EscapeKey(frames_[i].key));
        return pointer;
    }

    const std::string& sourceName_;
    std::vector<Frame> frames_;
};

// nlohmann's exception id for a number literal that overflows a double.
constexpr int kNumberOverflow = 406;

struct NumberOverflow {
    std::size_t line = 0, column = 0;  // 1-based, of the literal's first character
    std::string pointer;               // JSON pointer of the value, "/" for the root
    std::string token;                 // the literal as written
};

// A SAX handler that follows the JSON pointer of the value being parsed and records where the
// parser gives up (nlohmann calls parse_error with the lexer's position for an overflow).
class PointerTracker : public nlohmann::json::json_sax_t {
  public:
    bool null() override { return BeginValue(); }
    bool boolean(bool) override { return BeginValue(); }
    bool number_integer(number_integer_t) override { return BeginValue(); }
    bool number_unsigned(number_unsigned_t) override { return BeginValue(); }
    bool number_float(number_float_t, const string_t&) override { return BeginValue(); }
    bool string(string_t&) override { return BeginValue(); }
    bool binary(binary_t&) override { return BeginValue(); }
    bool start_object(std::size_t) override { return BeginContainer(false); }
    bool key(string_t& key) override {
        frames_.back().key = key;
        return true;
    }
    bool end_object() override { return EndContainer(); }
    bool start_array(std::size_t) override { return BeginContainer(true); }
    bool end_array() override { return EndContainer(); }
    bool parse_error(std::size_t position, const std::string& token,
                     const nlohmann::json::exception&) override {
        error_.pointer = NextPointer();
        error_.token = token;
        end_ = position;
        return false;
    }

    // The pointer of the value that would begin next (the one that failed).
    std::string NextPointer() const {
        std::string pointer;
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            const Frame& f = frames_[i];
            const bool last = i + 1 == frames_.size();
            pointer += '/';
            pointer +=
                f.array ? std::to_string(last ? f.elements : f.elements - 1) : EscapeKey(f.key);
        }
        return pointer.empty() ? "/" : pointer;
    }
    const NumberOverflow& Error() const { return error_; }
    std::size_t ErrorEnd() const { return end_; }  // bytes read up to the end of the bad token

  private:
    struct Frame {
        bool array = false;
        std::size_t elements = 0;
        std::string key;
    };
    bool BeginValue() {
        if (!frames_.empty() && frames_.back().array) ++frames_.back().elements;
        return true;
    }
    bool BeginContainer(bool array) {
        BeginValue();
        frames_.push_back({array, 0, {}});
        return true;
    }
    bool EndContainer() {
        frames_.pop_back();
        return true;
    }

    std::vector<Frame> frames_;
    NumberOverflow error_;
    std::size_t end_ = 0;
};

// Where the first overflowing number literal of `text` is: its line, column and pointer.
NumberOverflow LocateNumberOverflow(const std::string& text) {
    PointerTracker tracker;
    nlohmann::json::sax_parse(text, &tracker);
    NumberOverflow where = tracker.Error();
    // The literal's first byte: the parser's position is just past it.
    const std::size_t begin = tracker.ErrorEnd() - std::min(tracker.ErrorEnd(), where.token.size());
    where.line = 1, where.column = 1;
    for (std::size_t i = 0; i < begin && i < text.size(); ++i) {
        if (text[i] == '\n')
            ++where.line, where.column = 1;
        else
            ++where.column;
    }
    return where;
}

}  // namespace

namespace {

// The most bytes parsing may take, beside the text: nlohmann's document of the worst text (empty
// arrays, "[],": 3 bytes each become a 16-byte value and a 32-byte vector, and the parent's vector
// doubles) needs about 40 bytes a byte; kParseBytesPerTextByte leaves room above that.
constexpr std::size_t kParseBytesPerTextByte = 64, kParseBaseBytes = std::size_t{64} << 20;

// A number from /proc (`file`'s line starting with `key`, in kB) as bytes; 0 when not there.
std::size_t ProcBytes(const char* file, std::string_view key) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
        if (line.starts_with(key)) return std::stoull(line.substr(key.size())) * 1024;
    return 0;
}

// What this process can still take: the address space left under its limit (ulimit -v) and the
// memory the machine has available, three quarters of the smaller (a quarter kept for
// fragmentation and what the rest of the process takes); unbounded where neither says.
std::size_t ReadMemoryLeft() {
    std::size_t left = std::numeric_limits<std::size_t>::max();
    struct rlimit limit {};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        const std::size_t used = ProcBytes("/proc/self/status", "VmSize:");
        left = limit.rlim_cur > used ? limit.rlim_cur - used : 0;
    }
    if (const std::size_t available = ProcBytes("/proc/meminfo", "MemAvailable:"); available > 0)
        left = std::min(left, available);
    return left == std::numeric_limits<std::size_t>::max() ? left : left / 4 * 3;
}

// ReadMemoryLeft, read again at most every kMemoryLeftSeconds: a resume journal parses one JSON
// line per light, and two /proc reads a line would cost more than the parse.
constexpr double kMemoryLeftSeconds = 0.1;
std::size_t MemoryLeft() {
    static std::mutex mutex;
    static std::chrono::steady_clock::time_point readAt;
    static std::size_t left = 0;
    const std::lock_guard lock(mutex);
    const auto now = std::chrono::steady_clock::now();
    if (left == 0 || std::chrono::duration<double>(now - readAt).count() > kMemoryLeftSeconds) {
        left = std::max<std::size_t>(ReadMemoryLeft(), 1);
        readAt = now;
    }
    return left;
}

// nlohmann's DOM of `text` under a ScopedAllocationCap: the cap refuses before the machine does,
// so the parse unwinds (nlohmann's destructor allocates as it frees) and the refusal is one
// InputError instead of std::terminate.
nlohmann::json ParseUnderCap(const std::string& text, const std::string& sourceName) {
    // Half of what is left for the parse, the other half open for its unwinding.
    const std::size_t cap =
        std::min(MemoryLeft() / 2, kParseBaseBytes + kParseBytesPerTextByte * text.size());
    std::optional<nlohmann::json> document;
    bool refused = false;
    {
        const spatial::ScopedAllocationCap scope(cap, cap);
        try {
            document = nlohmann::json::parse(text, DuplicateKeyCheck(sourceName));
        } catch (const std::bad_alloc&) {
            refused = true;
        }
        refused = refused || scope.Refused();
    }
    if (refused || !document)
        throw InputError(sourceName + ": " + std::to_string(text.size()) +
                         " bytes of JSON need more memory than this machine gives (" +
                         FormatBytes(static_cast<double>(cap)) + " were free to parse them)");
    return std::move(*document);
}

}  // namespace

nlohmann::json ParseJsonText(const std::string& text, const std::string& sourceName) {
    // nlohmann's lexer takes a NUL byte for the end of the input, so `{...}\0garbage` would parse.
    if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
        const std::size_t line = 1 + std::count(text.begin(), text.begin() + nul, '\n');
        const std::size_t lineStart = text.rfind('\n', nul);
        const std::size_t column = lineStart == std::string::npos ? nul + 1 : nul - lineStart;
        throw InputError(sourceName + ":" + std::to_string(line) + ":" + std::to_string(column) +
                         ": invalid JSON: a NUL byte (a case file is text)");
    }
    try {
        return ParseUnderCap(text, sourceName);
    } catch (const nlohmann::json::parse_error& e) {
        // Line and column of the offending byte (nlohmann reports a 1-based byte count).
        std::size_t line = 1, column = 1;
        const std::size_t end = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
        for (std::size_t i = 0; i < end; ++i) {
            if (text[i] == '\n')
                ++line, column = 1;
            else
                ++column;
        }
        std::string reason = e.what();
        // Keep nlohmann's reason, drop its "[json.exception.parse_error.101] parse error at ...: "
        // prefix.
        if (const auto colon = reason.find(": "); colon != std::string::npos)
            reason = reason.substr(colon + 2);
        throw InputError(sourceName + ":" + std::to_string(line) + ":" + std::to_string(column) +
                         ": invalid JSON: " + reason);
    } catch (const nlohmann::json::out_of_range& e) {
        // A literal that does not fit a double (1e400): nlohmann's DOM parser drops its position,
        // so a second, SAX pass finds the line, column and pointer of the number.
        if (e.id != kNumberOverflow) throw;
        const NumberOverflow where = LocateNumberOverflow(text);
        throw InputError(sourceName + ":" + std::to_string(where.line) + ":" +
                         std::to_string(where.column) + ": " + where.pointer + ": number " +
                         where.token + " does not fit a double (numbers must be finite)");
    }
}

namespace {

// The bytes of a case file, with ParseJsonFile's checks before and while reading.
std::string ReadCaseText(const std::filesystem::path& path) {
    // Only a regular file of bounded size: /dev/zero would be read without end, a FIFO would block.
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (error || !std::filesystem::exists(status))
        throw InputError(path.string() + ": cannot open the case file");
    if (!std::filesystem::is_regular_file(status))
        throw InputError(path.string() + ": not a regular file (a case is a JSON file)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot open the case file");
    std::string text(kMaxCaseFileBytes + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxCaseFileBytes)
        throw InputError(path.string() + ": larger than " +
                         std::to_string(kMaxCaseFileBytes >> 20) +
                         " MiB, the most a case file may be");
    text.shrink_to_fit();
    return text;
}

}  // namespace

nlohmann::json ParseJsonFile(const std::filesystem::path& path) {
    return ParseJsonText(ReadCaseText(path), path.string());
}

void JsonField::Fail(const std::string& reason) const {
    throw InputError(Printable((pointer_.empty() ? std::string("/") : pointer_) + ": " + reason));
}

namespace {

// ExpectObject's check, for keys given at compile time or at run time.
template <class Keys>
void CheckObjectKeys(const JsonField& field, const nlohmann::json& value, const Keys& required,
                     const Keys& optional) {
    if (!value.is_object()) field.Fail("must be an object, got " + TypeName(value));
    for (const auto& [key, _] : value.items()) {
        bool known = false;
        for (std::string_view k : required) known |= key == k;
        for (std::string_view k : optional) known |= key == k;
        if (!known) {
            std::string allowed;
            for (std::string_view k : required)
                allowed += (allowed.empty() ? "" : ", ") + std::string(k);
            for (std::string_view k : optional)
                allowed += (allowed.empty() ? "" : ", ") + std::string(k);
            throw InputError(field.Pointer() + "/" + EscapeKey(key) +
                             ": unknown key (allowed here: " + allowed + ")");
        }
    }
    for (std::string_view k : required)
        if (!value.contains(std::string(k)))
            throw InputError(field.Pointer() + "/" + EscapeKey(k) + ": required key is missing");
}

}  // namespace

void JsonField::ExpectObject(std::initializer_list<std::string_view> required,
                             std::initializer_list<std::string_view> optional) const {
    CheckObjectKeys(*this, *value_, required, optional);
}

void JsonField::ExpectKeys(const std::vector<std::string>& keys) const {
    CheckObjectKeys(*this, *value_, keys, std::vector<std::string>{});
}

bool JsonField::Has(std::string_view key) const {
    return value_->is_object() && value_->contains(std::string(key));
}

JsonField JsonField::operator[](std::string_view key) const {
    if (!value_->is_object()) Fail("must be an object, got " + TypeName(*value_));
    const auto it = value_->find(std::string(key));
    if (it == value_->end())
        throw InputError(pointer_ + "/" + EscapeKey(key) + ": required key is missing");
    return JsonField(*it, pointer_ + "/" + EscapeKey(key));
}

std::vector<JsonField> JsonField::Array(std::size_t minSize) const {
    if (!value_->is_array()) Fail("must be an array, got " + TypeName(*value_));
    if (value_->size() < minSize)
        Fail("must have at least " + std::to_string(minSize) + " elements, got " +
             std::to_string(value_->size()));
    std::vector<JsonField> out;
    for (std::size_t i = 0; i < value_->size(); ++i)
        out.emplace_back((*value_)[i], pointer_ + "/" + std::to_string(i));
    return out;
}

double JsonField::Number() const {
    if (!value_->is_number()) Fail("must be a number, got " + TypeName(*value_));
    const double v = value_->get<double>();
    if (!std::isfinite(v)) Fail("must be finite, got " + FormatNumber(v));
    return v;
}

double JsonField::NumberIn(double lo, double hi, bool loOpen, bool hiOpen) const {
    const double v = Number();
    const bool ok = (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    if (!ok) {
        auto bound = [](double b) {
            return std::isinf(b) ? std::string(b > 0 ? "inf" : "-inf") : FormatNumber(b);
        };
        Fail("must be in " + std::string(loOpen ? "(" : "[") + bound(lo) + ", " + bound(hi) +
             (hiOpen ? ")" : "]") + ", got " + FormatNumber(v));
    }
    return v;
}

double JsonField::Positive() const {
    return NumberIn(0.0, std::numeric_limits<double>::infinity(), true, true);
}

long long JsonField::Integer(long long lo, long long hi) const {
    if (!value_->is_number_integer() && !value_->is_number_unsigned()) {
        if (value_->is_number()) {
            const double v = value_->get<double>();
            Fail("must be an integer, got " + FormatNumber(v));
        }
        Fail("must be an integer, got " + TypeName(*value_));
    }
    if (value_->is_number_unsigned() &&
        value_->get<unsigned long long>() > static_cast<unsigned long long>(hi))
        Fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
             value_->dump());
    const long long v = value_->get<long long>();
    if (v < lo || v > hi)
        Fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
             std::to_string(v));
    return v;
}

std::string JsonField::String() const {
    if (!value_->is_string()) Fail("must be a string, got " + TypeName(*value_));
    return value_->get<std::string>();
}

Eigen::Vector2d JsonField::Vec2() const {
    const auto items = Array();
    if (items.size() != 2)
        Fail("must be an array of 2 numbers, got " + std::to_string(items.size()) + " elements");
    return {items[0].Number(), items[1].Number()};
}

Eigen::Vector3d JsonField::Vec3() const {
    const auto items = Array();
    if (items.size() != 3)
        Fail("must be an array of 3 numbers, got " + std::to_string(items.size()) + " elements");
    return {items[0].Number(), items[1].Number(), items[2].Number()};
}

CaseFile ReadCaseFile(const std::filesystem::path& path) {
    std::string text = ReadCaseText(path);
    nlohmann::json document = ParseJsonText(text, path.string());
    return {path, std::move(text), std::move(document)};
}

}  // namespace lexel::cases
