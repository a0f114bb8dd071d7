#include "lexel/cases/plot/canvas.h"

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <system_error>

namespace lexel::plot {

void SetColour(cairo_t* cr, Rgb c, double alpha) {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

void SetFont(cairo_t* cr, double size, bool bold) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

void ShowText(cairo_t* cr, double pxX, double pxY, const std::string& text, double alignX,
              double alignY) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_move_to(cr, pxX - alignX * extents.width - extents.x_bearing,
                  pxY - alignY * extents.height - extents.y_bearing);
    cairo_show_text(cr, text.c_str());
}

void ShowBaselineText(cairo_t* cr, double pxX, double pxY, const std::string& text, double alignX) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_move_to(cr, pxX - alignX * extents.width - extents.x_bearing, pxY);
    cairo_show_text(cr, text.c_str());
}

// `text` cut at spaces into lines no wider than `pxWidth` in the context's current font.
std::vector<std::string> WrapToWidth(cairo_t* cr, const std::string& text, double pxWidth) {
    std::vector<std::string> lines;
    std::string line;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(' ', start);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(start, end - start);
        start = end + 1;
        const std::string candidate = line.empty() ? word : line + " " + word;
        cairo_text_extents_t extents;
        cairo_text_extents(cr, candidate.c_str(), &extents);
        if (!line.empty() && extents.x_advance > pxWidth) {
            lines.push_back(line);
            line = word;
        } else {
            line = candidate;
        }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

// Text with its origin at pxX and the font's ascent below pxTop, so lines align by their
// baselines whatever their ink; centred on pxY when `centreY`.
void ShowLine(cairo_t* cr, double pxX, double pxY, const std::string& text, bool centreY) {
    cairo_font_extents_t font;
    cairo_font_extents(cr, &font);
    cairo_move_to(cr, pxX, centreY ? pxY + (font.ascent - font.descent) / 2 : pxY + font.ascent);
    cairo_show_text(cr, text.c_str());
}

double TextWidth(cairo_t* cr, const std::string& text) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    return extents.x_advance;
}

void RenderPng(const std::string& pngPath, int pxWidth, int pxHeight,
               const std::function<void(cairo_t*)>& draw) {
    const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, pxWidth, pxHeight), cairo_surface_destroy);
    const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> context(cairo_create(surface.get()),
                                                                     cairo_destroy);
    cairo_t* cr = context.get();
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_BEST);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    draw(cr);
    cairo_status_t status = cairo_status(cr);
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface.get());
    if (status != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(pngPath + ": " + cairo_status_to_string(status));
    cairo_surface_flush(surface.get());
    const std::string partialPath = pngPath + ".partial.png";
    status = cairo_surface_write_to_png(surface.get(), partialPath.c_str());
    std::error_code ignored;
    if (status != CAIRO_STATUS_SUCCESS) {
        std::filesystem::remove(partialPath, ignored);
        throw std::runtime_error(pngPath + ": " + cairo_status_to_string(status));
    }
    std::error_code error;
    std::filesystem::rename(partialPath, pngPath, error);
    if (error) {
        std::filesystem::remove(partialPath, ignored);
        throw std::runtime_error(pngPath + ": " + error.message());
    }
}

void WithMeasuringCanvas(const std::function<void(cairo_t*)>& measure) {
    const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> scratch(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1), cairo_surface_destroy);
    const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(scratch.get()),
                                                                cairo_destroy);
    measure(cr.get());
}

}  // namespace lexel::plot
