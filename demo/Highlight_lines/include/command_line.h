// Small helpers for the command lines of the command-line programs (demo/Highlight_lines).
#ifndef HIGHLIGHT_LINES_DEMO_COMMAND_LINE_H
#define HIGHLIGHT_LINES_DEMO_COMMAND_LINE_H

#include <cstdlib>
#include <iostream>
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

// The number after argv[i] (i is advanced), or a clear error.
inline double number(int& i, int argc, char** argv)
{
  if (++i >= argc)
    fail(std::string("missing value after ") + argv[i - 1]);
  char* end = nullptr;
  const double value = std::strtod(argv[i], &end);
  if (end == argv[i] || *end != '\0')
    fail(std::string("not a number: ") + argv[i]);
  return value;
}

} // namespace command_line

#endif
