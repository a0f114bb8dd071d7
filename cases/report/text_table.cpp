#include "lexel/cases/report/text_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
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

std::string CsvNumber(double value) {
    if (std::isnan(value)) return "";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    if (value == 0.0) return "0";  // -0 too
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, r.ptr);
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

std::string HtmlText(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

// One per code point (continuation bytes are 10xxxxxx), so "σ" and "∞" take one column like the
// ASCII around them; combining diacritical marks (U+0300–U+036F, UTF-8 CC 80 – CD AF: the bar of
// "S̄") take none.
std::size_t DisplayWidth(std::string_view text) {
    std::size_t width = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        const auto next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0;
        const bool combining = c == 0xCC || (c == 0xCD && next <= 0xAF);
        width += (c & 0xC0) != 0x80 && !combining;
    }
    return width;
}

namespace {

std::vector<std::string> Lines(const std::string& cell) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (std::size_t end; (end = cell.find('\n', start)) != std::string::npos; start = end + 1)
        lines.push_back(cell.substr(start, end - start));
    lines.push_back(cell.substr(start));
    return lines;
}

// A header cell on one line: its lines joined by `separator`.
std::string Joined(const std::string& cell, std::string_view separator) {
    std::string out;
    for (const std::string& line : Lines(cell)) {
        if (!out.empty()) out += separator;
        out += line;
    }
    return out;
}

void TrimRight(std::string& line) {
    while (!line.empty() && line.back() == ' ') line.pop_back();
}

}  // namespace

std::string TextTable::RenderColumns(const std::vector<std::size_t>& columns) const {
    std::vector<std::vector<std::string>> header;
    std::size_t headerHeight = 1;
    for (std::size_t c : columns) {
        header.push_back(c < rows_[0].size() ? Lines(rows_[0][c]) : std::vector<std::string>{""});
        headerHeight = std::max(headerHeight, header.back().size());
    }
    std::vector<std::size_t> width(columns.size(), 0);
    for (std::size_t k = 0; k < columns.size(); ++k) {
        for (const std::string& line : header[k]) width[k] = std::max(width[k], DisplayWidth(line));
        for (std::size_t r = 1; r < rows_.size(); ++r)
            if (columns[k] < rows_[r].size())
                width[k] = std::max(width[k], DisplayWidth(rows_[r][columns[k]]));
    }
    const auto line = [&](const auto& cellOf) {
        std::string out;
        for (std::size_t k = 0; k < columns.size(); ++k) {
            const std::string cell = cellOf(k);
            const std::string pad(width[k] - DisplayWidth(cell), ' ');
            out += (k ? "  " : "") + (k == 0 ? cell + pad : pad + cell);
        }
        TrimRight(out);
        return out + '\n';
    };
    std::string out;
    for (std::size_t h = 0; h < headerHeight; ++h)
        out += line([&](std::size_t k) {
            const std::size_t skip = headerHeight - header[k].size();  // bottom-aligned
            return h < skip ? std::string() : header[k][h - skip];
        });
    std::size_t total = 0;
    for (std::size_t k = 0; k < width.size(); ++k) total += width[k] + (k ? 2 : 0);
    out += std::string(total, '-') + '\n';
    for (std::size_t r = 1; r < rows_.size(); ++r)
        out += line([&](std::size_t k) {
            return columns[k] < rows_[r].size() ? rows_[r][columns[k]] : std::string();
        });
    return out;
}

std::string TextTable::Render(std::size_t maxColumns) const {
    std::size_t count = 0;
    for (const auto& row : rows_) count = std::max(count, row.size());
    std::vector<std::size_t> width(count, 0);
    for (std::size_t r = 0; r < rows_.size(); ++r)
        for (std::size_t c = 0; c < rows_[r].size(); ++c)
            for (const std::string& line : r == 0 ? Lines(rows_[r][c]) : std::vector{rows_[r][c]})
                width[c] = std::max(width[c], DisplayWidth(line));
    // Whole columns into blocks of at most `limit` columns, each led by the first column.
    const auto cut = [&](std::size_t limit) {
        std::vector<std::vector<std::size_t>> blocks = {{0}};
        std::size_t used = count ? width[0] : 0;
        for (std::size_t c = 1; c < count; ++c) {
            if (blocks.back().size() > 1 && used + 2 + width[c] > limit) {
                blocks.push_back({0});
                used = width[0];
            }
            blocks.back().push_back(c);
            used += 2 + width[c];
        }
        return blocks;
    };
    std::vector<std::vector<std::size_t>> blocks = cut(maxColumns);
    if (blocks.size() > 1) {
        // As many blocks, of about equal width: no last block holding a single column.
        std::size_t rest = 0;
        for (std::size_t c = 1; c < count; ++c) rest += 2 + width[c];
        for (std::size_t limit = width[0] + (rest + blocks.size() - 1) / blocks.size();
             limit < maxColumns; ++limit) {
            std::vector<std::vector<std::size_t>> even = cut(limit);
            if (even.size() == blocks.size()) {
                blocks = std::move(even);
                break;
            }
        }
    }
    std::string out;
    for (std::size_t b = 0; b < blocks.size(); ++b)
        out += (b ? "\n" : "") + RenderColumns(blocks[b]);
    return out;
}

std::string TextTable::RenderMarkdown() const {
    std::ostringstream out;
    for (std::size_t r = 0; r < rows_.size(); ++r) {
        out << '|';
        for (const auto& cell : rows_[r]) out << ' ' << (r == 0 ? Joined(cell, " ") : cell) << " |";
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

std::string TextTable::RenderHtml(std::string_view cssClass) const {
    std::ostringstream out;
    out << "<table" << (cssClass.empty() ? "" : " class=\"" + HtmlText(cssClass) + "\"")
        << ">\n<thead><tr>";
    for (std::size_t c = 0; c < rows_[0].size(); ++c) {
        const std::string& cell = rows_[0][c];
        std::string lines;
        for (const std::string& line : Lines(cell))
            lines += (lines.empty() ? "" : "<br>") + HtmlText(line);
        out << (c > 0 ? "<th class=\"num\">" : "<th>") << lines << "</th>";
    }
    out << "</tr></thead>\n<tbody>\n";
    for (std::size_t r = 1; r < rows_.size(); ++r) {
        out << (classes_[r].empty() ? "<tr>" : "<tr class=\"" + HtmlText(classes_[r]) + "\">");
        for (std::size_t c = 0; c < rows_[r].size(); ++c) {
            const std::string& cell = rows_[r][c];
            out << (c > 0 ? "<td class=\"num\">" : "<td>") << HtmlText(cell) << "</td>";
        }
        out << "</tr>\n";
    }
    out << "</tbody>\n</table>\n";
    return out.str();
}

std::string WrapText(std::string_view text, std::size_t columns, std::string_view indent) {
    // Each line of the text on its own: '\n' is a hard break.
    if (const std::size_t newline = text.find('\n'); newline != std::string_view::npos) {
        const std::string_view rest = text.substr(newline + 1);
        return WrapText(text.substr(0, newline), columns, indent) +
               (text.substr(0, newline).find_first_not_of(' ') == std::string_view::npos ? "\n"
                                                                                         : "") +
               (rest.empty() ? "" : WrapText(rest, columns, indent));
    }
    std::string out;
    std::size_t start = text.find_first_not_of(' ');
    if (start == std::string_view::npos) return "";
    std::string line(text.substr(0, start));  // the text's own leading spaces stay
    const std::size_t lead = start;
    while (start < text.size()) {
        std::size_t end = text.find(' ', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view word = text.substr(start, end - start);
        start = end + 1;
        if (word.empty()) continue;
        const bool fresh = line.size() == (out.empty() ? lead : indent.size());
        if (!fresh && DisplayWidth(line) + 1 + DisplayWidth(word) > columns) {
            out += line + '\n';
            line = std::string(indent);
        } else if (!fresh) {
            line += ' ';
        }
        line += word;
    }
    if (!line.empty()) out += line + '\n';
    return out;
}

std::string SectionsText(const std::vector<ReportSection>& sections) {
    std::string out;
    for (std::size_t i = 0; i < sections.size(); ++i) {
        const ReportSection& s = sections[i];
        out += (i ? "\n" : "") + WrapText(s.title, kTerminalColumns, "  ") + s.table.Render();
        for (const std::string& note : s.notes) out += WrapText(note, kTerminalColumns, "  ");
    }
    return out;
}

std::string SectionsMarkdown(const std::vector<ReportSection>& sections) {
    std::string out;
    for (std::size_t i = 0; i < sections.size(); ++i) {
        const ReportSection& s = sections[i];
        out += (i ? "\n" : "") + ("## " + s.title + "\n\n");
        if (!s.explanation.empty()) out += s.explanation + "\n\n";
        out += s.table.RenderMarkdown();
        for (const std::string& note : s.notes) out += "\n" + note + "\n";
    }
    return out;
}

}  // namespace lexel::cases
