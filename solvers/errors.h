// The two exception types lexel throws for bad input.
//
// DomainError: a domain function cannot serve its input — degenerate geometry, a light inside the
// geometry, no light matrix that sees every visible point. The message says why in the domain's
// terms ("the light lies on segment 2 of polyline 0"); subject() and index() say which input, so
// that the layer that read the input (the case loader, cases/) can name the field.
//
// InputError: bad input in the user's terms, one line naming a case file's JSON pointer or a
// command-line flag and the reason. Only cases/ (the loader, the runners, the command line)
// throws it; the CLI prints it and exits with status 2.
//
// Violated preconditions of library functions (a span of the wrong size, a null context) are
// std::invalid_argument: programming errors, not input.
#pragma once

#include <array>
#include <stdexcept>
#include <string>

namespace lexel {

class InputError : public std::runtime_error {
  public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// Which input a DomainError is about.
enum class Subject {
    kCamera,    // the viewer: its position, or what it sees
    kLight,     // the light: its position or direction
    kGeometry,  // the scene's geometry as a whole
    kSegment,   // flatland: one segment, index() = {polyline, segment}
    kLexels,    // the shadow map's lexel (texel) budget
};

class DomainError : public std::runtime_error {
  public:
    // index: the element of `subject` the error is about ({-1, -1}: the whole); for kLight and
    // kCamera it may name the segment or polyline they collide with.
    DomainError(Subject subject, const std::string& message, std::array<int, 2> index = {-1, -1})
        : std::runtime_error(message), subject_(subject), index_(index) {}
    Subject subject() const { return subject_; }
    std::array<int, 2> index() const { return index_; }

  private:
    Subject subject_;
    std::array<int, 2> index_;
};

}  // namespace lexel
