#include "lexel/cases/load/case_name.h"

#include <cstdio>

#include "lexel/solvers/errors.h"

namespace lexel::cases {

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
