#include "cli/Commands.h"
#include <iostream>

int main(int argc, char** argv)
{
  return clash4d::run_cli(argc, argv, std::cout, std::cerr);
}
