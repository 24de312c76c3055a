// Small helpers for the command lines of the command-line programs (demo/Highlight_lines): the
// loop over the arguments, the values of an option, and the options the programs share (an
// explicit light setup, the picture size).
#ifndef HIGHLIGHT_LINES_DEMO_COMMAND_LINE_H
#define HIGHLIGHT_LINES_DEMO_COMMAND_LINE_H

#include <CGAL/Highlight_lines/Light_setup.h>
#include <CGAL/Origin.h>

#include <array>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

namespace command_line {

// The program's name, for messages.
inline std::string& program()
{
  static std::string name = "example";
  return name;
}

[[noreturn]] inline void fail(const std::string& message)
{
  std::cerr << program() << ": " << message << "\n(see --help)\n";
  std::exit(2);
}

// The argument after argv[i] (i is advanced), or a clear error.
inline std::string word(int& i, int argc, char** argv)
{
  if (++i >= argc)
    fail(std::string("missing value after ") + argv[i - 1]);
  return argv[i];
}

// The number after argv[i] (i is advanced), or a clear error.
inline double number(int& i, int argc, char** argv)
{
  const std::string text = word(i, argc, argv);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0')
    fail("not a number: " + text);
  return value;
}

// The three numbers after argv[i].
inline std::array<double, 3> triple(int& i, int argc, char** argv)
{
  const double x = number(i, argc, argv), y = number(i, argc, argv), z = number(i, argc, argv);
  return {x, y, z};
}

// Reads the command line: --help (or -h) prints `usage` and exits; an option (an argument
// starting with '-') goes to `read_option(name, i)`, which reads its values through i and
// returns false if it does not know the option (an error); any other argument is the mesh
// (`read_mesh(argument)`).
template <typename ReadOption, typename ReadMesh>
void parse(int argc, char** argv, const char* usage, ReadOption read_option, ReadMesh read_mesh)
{
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage;
      std::exit(0);
    }
    if (!a.empty() && a[0] == '-') {
      if (!read_option(a, i))
        fail("unknown option " + a);
    } else
      read_mesh(a);
  }
}

// An explicit light setup: --base X Y Z, --direction X Y Z, --normal X Y Z and --spacing S,
// all four or none.
struct Light_options
{
  std::optional<std::array<double, 3>> base, direction, normal;
  std::optional<double> spacing;

  // Reads the option `a` if it is one of the four; false otherwise.
  bool read(const std::string& a, int& i, int argc, char** argv)
  {
    if (a == "--base")
      base = triple(i, argc, argv);
    else if (a == "--direction")
      direction = triple(i, argc, argv);
    else if (a == "--normal")
      normal = triple(i, argc, argv);
    else if (a == "--spacing")
      spacing = number(i, argc, argv);
    else
      return false;
    return true;
  }

  void check() const
  {
    const int given = bool(base) + bool(direction) + bool(normal) + bool(spacing);
    if (given != 0 && given != 4)
      fail("--base, --direction, --normal and --spacing go together");
  }

  bool given() const { return bool(base); }

  // The setup they give (given() must hold); the Light_setup constructor checks it.
  template <typename K>
  CGAL::Highlight_lines::Light_setup<K> setup() const
  {
    auto vector = [](const std::array<double, 3>& v) {
      return typename K::Vector_3(v[0], v[1], v[2]);
    };
    return CGAL::Highlight_lines::Light_setup<K>(CGAL::ORIGIN + vector(*base), vector(*direction),
                                                 vector(*normal), *spacing);
  }
};

// The picture size: --size W H.
struct Picture_size
{
  int width, height;

  bool read(const std::string& a, int& i, int argc, char** argv)
  {
    if (a != "--size")
      return false;
    width = int(number(i, argc, argv));
    height = int(number(i, argc, argv));
    return true;
  }

  void check(int smallest, int largest) const
  {
    if (width < smallest || height < smallest || width > largest || height > largest)
      fail("--size must be between " + std::to_string(smallest) + " and " +
           std::to_string(largest) + " pixels");
  }
};

} // namespace command_line

#endif
