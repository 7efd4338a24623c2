// libFuzzer target: the CCD query readers (ccd/Ccd_reader: the benchmark's
// CSV and JSON lines) and each query's approximations. The first byte picks
// the format and the --type given (none, vertex-face, edge-edge), the rest
// is the file. Bad input must end in Input_error with exit 2 or 3; anything
// else escaping, a crash, a leak or a hang is a finding, and so is a query
// whose nearest double is outside its enclosure.
#include "ccd/Ccd_reader.h"
#include "fuzz/Read_or_refuse.h"
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace clash4d;
  if (size == 0) return 0;
  auto format = data[0] % 2 ? Ccd_reader::Format::json_lines : Ccd_reader::Format::csv;
  std::optional<Ccd_type> type;
  if (data[0] / 2 % 3 == 1) type = Ccd_type::vertex_face;
  if (data[0] / 2 % 3 == 2) type = Ccd_type::edge_edge;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
  read_or_refuse([&] {
    Ccd_reader reader(in, format, type);
    std::vector<Ccd_query> queries;
    while (reader.read(16, queries) > 0) {}
    for (const Ccd_query& q : queries)
      for (std::size_t i = 0; i < 8; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
          double x = q.nearest()[i][k];
          auto e = q.enclosure()[i][k];
          if (std::isfinite(x) && !(e.inf() <= x && x <= e.sup())) std::abort();
        }
  });
  return 0;
}
