// Scene files from outside (issue 11): whatever their bytes, a clear error, quickly, with the
// limit in the message; never a crash (toml11 3.7 crashed or read out of bounds on these), a
// hang or quadratic time.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "asperity/error.hpp"
#include "asperity/scene.hpp"

namespace {
using namespace asperity;

std::string parse_error(const std::string& text) {
  try {
    parse_scene(text, "test.toml");
  } catch (const Error& error) {
    return error.what();
  }
  return "(parsed)";
}

std::string read_error(const std::string& path) {
  try {
    read_scene_file(path);
  } catch (const Error& error) {
    return error.what();
  }
  return "(read)";
}

const std::string one_curve = "[[curve]]\ndistribution = \"weibull\"\nshape = 2\norders = [1]\nseparation = [0, 1]\n";

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST(SceneLimits, AGoodSceneStillParses) { EXPECT_EQ(parse_scene(one_curve, "x").curves.size(), 1u); }

TEST(SceneLimits, DeepNesting) {
  // 10,000 nested arrays in 20 KB: SIGSEGV in toml11 (unbounded recursion)
  const std::string deep = "a = " + std::string(10000, '[') + std::string(10000, ']') + "\n";
  EXPECT_CONTAINS(parse_error(deep), "line 1: lists or tables nested deeper than 4");
  EXPECT_CONTAINS(parse_error("a = [[[[[1]]]]]\n"), "nested deeper than 4");
  EXPECT_CONTAINS(parse_error("a = {b = {c = {d = {e = {f = 1}}}}}\n"), "nested deeper than 4");
  // brackets inside strings and comments do not count
  EXPECT_EQ(parse_scene("name = \"[[[[[[\" # [[[[[[[\n" + one_curve, "x").name, "[[[[[[");
}

TEST(SceneLimits, InvalidUtf8AndControlCharacters) {
  // found by fuzz/fuzz_scene: a heap-buffer-overflow read in toml11's literal-string parser
  EXPECT_CONTAINS(parse_error("' \xf5 'MiGauus"), "line 1: not valid UTF-8 (byte 245)");
  EXPECT_CONTAINS(parse_error("name = \"\xc0\xaf\"\n"), "not valid UTF-8");           // overlong
  EXPECT_CONTAINS(parse_error("name = \"\xed\xa0\x80\"\n"), "not valid UTF-8");       // surrogate
  EXPECT_CONTAINS(parse_error("name = \"\xf4\x90\x80\x80\"\n"), "not valid UTF-8");   // beyond U+10FFFF
  EXPECT_CONTAINS(parse_error("name = \"\xe2\x82\"\n"), "not valid UTF-8");           // cut short
  EXPECT_CONTAINS(parse_error(std::string("\n\nname = \"a\0b\"\n", 14)), "line 3: a control character (byte 0)");
  EXPECT_EQ(parse_scene("name = \"d\xc3\xa9j\xc3\xa0 \xe2\x9c\x93 \xf0\x9f\x99\x82\"\n" + one_curve, "x").name,
            "d\xc3\xa9j\xc3\xa0 \xe2\x9c\x93 \xf0\x9f\x99\x82");
}

TEST(SceneLimits, LongListsAreRefusedBeforeParsing) {
  // a 40,000-entry list took toml11 27 s (quadratic); 20,000 fit in a scene file's 64 KiB
  std::string list = "a = [";
  for (int i = 0; i < 20000; ++i) list += "1,";
  list += "1]\n";
  EXPECT_CONTAINS(parse_error(list), "more than 1024 list entries");
}

TEST(SceneLimits, CurveCountAndNames) {
  // 2,000 identical curves took the generator 50 s; here as many as fit in 64 KiB
  std::string many;
  while (many.size() + one_curve.size() <= scene_max_bytes) many += one_curve;
  EXPECT_CONTAINS(parse_error(many), "a scene has at most 64 curves");
  std::string sixty_four;
  for (int i = 0; i < 64; ++i) sixty_four += one_curve;
  EXPECT_EQ(parse_scene(sixty_four, "x").curves.size(), 64u);
  // a long name (a 64 KB scene name made the writer fail with "generator_options")
  EXPECT_CONTAINS(parse_error("name = \"" + std::string(300, 'n') + "\"\n" + one_curve),
                  "a name has at most 256 bytes");
  EXPECT_CONTAINS(parse_error("[[curve]]\nname = \"" + std::string(300, 'n') + "\"\n"), "a name has at most 256 bytes");
}

TEST(SceneLimits, FileSizeAndKind) {
  EXPECT_CONTAINS(parse_error(std::string(70000, '#')), "a scene file has at most 65536");
  const std::string dir = ASPERITY_TEST_BINARY_DIR;
  const std::string big = dir + "/big-scene.toml";
  std::ofstream(big) << std::string(70000, '#');
  EXPECT_CONTAINS(read_error(big), "(a scene file has at most 64 KiB)");
  EXPECT_CONTAINS(read_error(dir), "a directory");
  EXPECT_CONTAINS(read_error(dir + "/no-such-scene.toml"), "no such file");
  const std::string fifo = dir + "/scene.fifo";
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_CONTAINS(read_error(fifo), "not a regular file");  // with no writer: must not wait for one
  std::remove(fifo.c_str());
}

}  // namespace
