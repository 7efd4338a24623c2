#include "cli/Commands.h"
#include "compare/Subject_processes.h"
#include <iostream>

int main(int argc, char** argv)
{
  // The command owns its children: every subject's descendant ends with it.
  clash4d::subject_processes::keep_descendants();
  return clash4d::run_cli(argc, argv, std::cout, std::cerr);
}
