#include "lexel/cases/report/columns.h"

#include "lexel/cases/report/json_number.h"

namespace lexel::cases {

std::string CsvCell(const CellValue& value) {
    if (const auto* n = std::get_if<std::int64_t>(&value)) return std::to_string(*n);
    if (const auto* x = std::get_if<double>(&value)) return CsvNumber(*x);
    if (const auto* s = std::get_if<std::string>(&value)) return CsvText(*s);
    return "";
}

nlohmann::json JsonCell(const CellValue& value) {
    if (const auto* n = std::get_if<std::int64_t>(&value)) return *n;
    if (const auto* x = std::get_if<double>(&value)) return FiniteOrNull(*x);
    if (const auto* s = std::get_if<std::string>(&value)) return *s;
    return nullptr;
}

namespace {

std::function<std::string(const CellValue&)> NumberText(std::string (*format)(double, int),
                                                        int digits) {
    return [format, digits](const CellValue& value) {
        if (const auto* x = std::get_if<double>(&value)) return format(*x, digits);
        return TextCell(value);
    };
}

}  // namespace

std::string TextCell(const CellValue& value) {
    if (const auto* n = std::get_if<std::int64_t>(&value)) return std::to_string(*n);
    if (const auto* x = std::get_if<double>(&value)) return Significant(*x, 4);
    if (const auto* s = std::get_if<std::string>(&value)) return *s;
    return "";
}

std::function<std::string(const CellValue&)> SignificantText(int digits) {
    return NumberText(Significant, digits);
}

std::function<std::string(const CellValue&)> FixedText(int digits) {
    return NumberText(Fixed, digits);
}

}  // namespace lexel::cases
