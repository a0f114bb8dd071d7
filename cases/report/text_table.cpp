#include "lexel/cases/report/text_table.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace lexel::cases {

std::string Fixed(double value, int digits) {
    if (std::isnan(value)) return "";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    // Values that round to zero print as 0, never as "-0.000".
    if (std::abs(value) < 0.5 * std::pow(10.0, -digits)) value = 0.0;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
    return buffer;
}

std::string Significant(double value, int digits) {
    if (std::isnan(value)) return "";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    return buffer;
}

std::string CsvNumber(double value, int precision) {
    if (std::isnan(value)) return "";
    std::ostringstream out;
    out.precision(precision);
    out << value;
    return out.str();
}

std::string CsvText(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + '"';
}

std::string MarkdownLinkTarget(std::string_view fileName) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    for (const char c : fileName) {
        const auto byte = static_cast<unsigned char>(c);
        if ((byte < 0x80 && std::isalnum(byte)) || c == '.' || c == '_' || c == '~' || c == '-') {
            out += c;
        } else {
            out += '%';
            out += kHex[byte >> 4];
            out += kHex[byte & 15];
        }
    }
    return out;
}

namespace {
// Terminal columns of a UTF-8 string: one per code point (continuation bytes are 10xxxxxx), so
// "σ" and "∞" take one column like the ASCII around them; combining diacritical marks
// (U+0300–U+036F, UTF-8 CC 80 – CD AF: the bar of "S̄") take none.
std::size_t DisplayWidth(const std::string& text) {
    std::size_t width = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        const auto next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0;
        const bool combining = c == 0xCC || (c == 0xCD && next <= 0xAF);
        width += (c & 0xC0) != 0x80 && !combining;
    }
    return width;
}
}  // namespace

std::string TextTable::Render() const {
    std::vector<std::size_t> width;
    for (const auto& row : rows_)
        for (std::size_t c = 0; c < row.size(); ++c) {
            if (width.size() <= c) width.push_back(0);
            width[c] = std::max(width[c], DisplayWidth(row[c]));
        }
    std::ostringstream out;
    for (std::size_t r = 0; r < rows_.size(); ++r) {
        for (std::size_t c = 0; c < rows_[r].size(); ++c) {
            const std::string& cell = rows_[r][c];
            const std::string pad(width[c] - DisplayWidth(cell), ' ');
            out << (c ? "  " : "") << (c == 0 ? cell + pad : pad + cell);
        }
        out << '\n';
        if (r == 0) {
            std::size_t total = 0;
            for (std::size_t c = 0; c < width.size(); ++c) total += width[c] + (c ? 2 : 0);
            out << std::string(total, '-') << '\n';
        }
    }
    return out.str();
}

std::string TextTable::RenderMarkdown() const {
    std::ostringstream out;
    for (std::size_t r = 0; r < rows_.size(); ++r) {
        out << '|';
        for (const auto& cell : rows_[r]) out << ' ' << cell << " |";
        out << '\n';
        if (r == 0) {
            out << '|';
            for (std::size_t c = 0; c < rows_[0].size(); ++c)
                out << (c == 0 ? " --- |" : " ---: |");
            out << '\n';
        }
    }
    return out.str();
}

}  // namespace lexel::cases
