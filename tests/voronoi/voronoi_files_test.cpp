#include "voronoi/voronoi_files.h"

#include <catch2/catch.hpp>
#include <fstream>

#include "../support/temp_dir.h"
#include "core/error.h"

using namespace homesh;

namespace {

// Writes TEXT to the file NAME in DIR; its path.
std::string write_temp(const test::TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir / name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST_CASE("seed files: one 'x y' per line, errors name the file and line", "[voronoi][files]") {
  const test::TempDir dir;
  const std::string good = write_temp(dir, "seeds_good.txt", "# seeds\n0.5 0.25\n\n  1e-1 -2\n");
  const SeedList s = read_seed_file(good);
  REQUIRE(s.points.cols() == 2);
  CHECK(s.points(0, 0) == 0.5);
  CHECK(s.points(1, 1) == -2.0);
  CHECK(s.lines == std::vector<int>{2, 4});
  const std::string bad = write_temp(dir, "seeds_bad.txt", "0 0\n1 2 3\n");
  CHECK_THROWS_WITH(read_seed_file(bad),
                    Catch::Contains(bad + ":2:") && Catch::Contains("expected 'x y', found 3"));
  const std::string word = write_temp(dir, "seeds_word.txt", "0 0\n1 nan\n");
  CHECK_THROWS_WITH(read_seed_file(word), Catch::Contains(":2: 'nan' is not a finite number"));
  CHECK_THROWS_WITH(read_seed_file(write_temp(dir, "seeds_empty.txt", "# none\n")),
                    Catch::Contains("holds no seed"));
  CHECK_THROWS_WITH(read_seed_file("/nonexistent/seeds.txt"), Catch::Contains("cannot be read"));
}

TEST_CASE("metric files: a coarse grid of SPD tensors", "[voronoi][files]") {
  const test::TempDir dir;
  const std::string good = write_temp(dir, "metric_good.txt",
                                      "# 2 x 2\ngrid 2 2 0 0 1 2\n100 0 100\n400 0 25\n"
                                      "100 0 100\n100 10 100\n");
  const MetricField m = read_metric_file(good);
  CHECK(m.coarse().nx == 2);
  CHECK(m.coarse().dy == 2.0);
  CHECK(m.metric(1)(0, 0) == 400.0);
  CHECK(m.metric(3)(1, 0) == 10.0);
  const std::string not_spd =
      write_temp(dir, "metric_spd.txt", "grid 2 2 0 0 1 1\n1 0 1\n1 2 1\n1 0 1\n1 0 1\n");
  CHECK_THROWS_WITH(read_metric_file(not_spd),
                    Catch::Contains(not_spd + ":3:") && Catch::Contains("not symmetric positive"));
  const std::string short_file = write_temp(dir, "metric_short.txt", "grid 2 2 0 0 1 1\n1 0 1\n");
  CHECK_THROWS_WITH(read_metric_file(short_file),
                    Catch::Contains("1 tensor lines") && Catch::Contains("need 4"));
  const std::string header = write_temp(dir, "metric_header.txt", "2 2 0 0 1 1\n");
  CHECK_THROWS_WITH(read_metric_file(header), Catch::Contains(":1: expected the header"));
  const std::string box = write_temp(dir, "metric_box.txt", "grid 2 1 0 0 1 1\n");
  CHECK_THROWS_WITH(read_metric_file(box), Catch::Contains("NX, NY >= 2"));
  // Found by fuzz_voronoi_files: counts beyond int and boxes of infinite width.
  const std::string huge = write_temp(dir, "metric_huge.txt", "grid 1e300 2 0 0 1 1\n");
  CHECK_THROWS_WITH(read_metric_file(huge),
                    Catch::Contains(huge + ":1:") && Catch::Contains("at most 1e7"));
  const std::string wide = write_temp(dir, "metric_wide.txt", "grid 2 2 -1e308 0 1e308 1\n");
  CHECK_THROWS_WITH(read_metric_file(wide), Catch::Contains("finite XMAX > XMIN"));
}
