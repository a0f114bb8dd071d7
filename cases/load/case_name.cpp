#include "lexel/cases/load/case_name.h"

#include <cstdio>

#include "lexel/solvers/errors.h"

namespace lexel::cases {

namespace {

// The offset of the first byte of `text` that does not begin or continue a well-formed UTF-8
// sequence (Unicode 15, Table 3-7: no overlong forms, no surrogates, at most U+10FFFF), or npos.
std::size_t InvalidUtf8At(std::string_view text) {
    for (std::size_t at = 0; at < text.size();) {
        const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
        const unsigned char lead = byte(at);
        std::size_t length = 1;
        unsigned char lo = 0x80, hi = 0xBF;  // the second byte's range
        if (lead < 0x80) {
            ++at;
            continue;
        } else if (lead >= 0xC2 && lead <= 0xDF) {
            length = 2;
        } else if (lead >= 0xE0 && lead <= 0xEF) {
            length = 3;
            if (lead == 0xE0) lo = 0xA0;
            if (lead == 0xED) hi = 0x9F;
        } else if (lead >= 0xF0 && lead <= 0xF4) {
            length = 4;
            if (lead == 0xF0) lo = 0x90;
            if (lead == 0xF4) hi = 0x8F;
        } else {
            return at;
        }
        if (at + length > text.size() || byte(at + 1) < lo || byte(at + 1) > hi) return at;
        for (std::size_t i = 2; i < length; ++i)
            if (byte(at + i) < 0x80 || byte(at + i) > 0xBF) return at;
        at += length;
    }
    return std::string_view::npos;
}

}  // namespace

std::optional<std::string> CaseNameProblem(std::string_view name) {
    const std::string prefix = "not a safe file stem: ";
    if (name.empty()) return prefix + "empty";
    if (name.size() > kMaxCaseNameBytes)
        return prefix + std::to_string(name.size()) + " bytes, at most " +
               std::to_string(kMaxCaseNameBytes);
    for (const char c : name) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7F) {
            char code[8];
            std::snprintf(code, sizeof code, "%04X", byte);
            return prefix + "contains the control character U+" + code;
        }
        if (c == '/' || c == '\\') return prefix + "contains '" + c + "'";
    }
    if (name.find("..") != std::string_view::npos) return prefix + "contains '..'";
    // The name is written into JSON reports, which hold UTF-8 text only.
    if (const std::size_t at = InvalidUtf8At(name); at != std::string_view::npos) {
        char code[8];
        std::snprintf(code, sizeof code, "%02X", static_cast<unsigned char>(name[at]));
        return prefix + "not UTF-8 (byte 0x" + code + " at offset " + std::to_string(at) + ")";
    }
    return std::nullopt;
}

std::string CaseNameOf(const JsonField& root, const std::string& fallbackName) {
    if (root.Has("name")) {
        const JsonField field = root["name"];
        std::string name = field.String();
        if (const auto problem = CaseNameProblem(name)) field.Fail(*problem);
        return name;
    }
    // No /name: the file stem names the outputs, under the same rule.
    if (const auto problem = CaseNameProblem(fallbackName))
        throw InputError("/name: absent, and the file's stem is " + *problem);
    return fallbackName;
}

}  // namespace lexel::cases
