// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INVALID_INPUT_H
#define CGAL_HIGHLIGHT_LINES_INVALID_INPUT_H

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Highlight_lines {

/*!
\ingroup PkgHighlightLinesRef

Exception thrown by the functions of this package when the user's input cannot be processed:
an invalid light setup, a face that is not a triangle, a non-finite coordinate, a degenerate
face, a face range that is empty or does not belong to the mesh, an invalid named parameter, a
fairing region too small or too large for the fairing's double arithmetic.

Whenever this exception is thrown, the mesh passed by the user is left exactly as it was.
The message names the problem and, where there is one, the element (vertex or face index,
as given by the index property map in use).
*/
class Invalid_input : public std::invalid_argument
{
public:
  /// What is wrong with the input.
  enum class Problem {
    INVALID_LIGHT_SETUP,   ///< zero or non-finite vectors, direction not in the plane, spacing <= 0
    NON_TRIANGLE_FACE,     ///< a face with other than three vertices
    NON_FINITE_COORDINATE, ///< a vertex with a NaN or infinite coordinate
    DEGENERATE_FACE,       ///< a face whose three vertices are collinear
    EMPTY_FACE_RANGE,      ///< no face given where at least one is needed
    FACE_NOT_IN_MESH,      ///< a face descriptor that does not belong to the mesh
    NO_MOVABLE_VERTEX,     ///< a fairing region without any movable vertex
    INVALID_PARAMETER,     ///< a named parameter with a value out of its domain
    SCALE_OUT_OF_RANGE     ///< a fairing region whose size is outside [1e-60, 1e60]
  };

  /// Returned by `element()` when the problem is not attached to one mesh element.
  static constexpr std::size_t no_element = (std::numeric_limits<std::size_t>::max)();

  /// Creates the exception for `problem`, with the text returned by `what()` and the index of
  /// the offending element, if there is one.
  Invalid_input(Problem problem, const std::string& message, std::size_t element = no_element)
      : std::invalid_argument(message), problem_(problem), element_(element)
  {
  }

  /// The kind of problem.
  Problem problem() const { return problem_; }

  /// Index of the offending vertex or face, or `no_element`.
  std::size_t element() const { return element_; }

private:
  Problem problem_;
  std::size_t element_;
};

} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INVALID_INPUT_H
