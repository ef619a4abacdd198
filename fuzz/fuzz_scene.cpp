// libFuzzer target: a scene file's text (parse_scene, with toml11 behind check_scene_text).
// Whatever the bytes: a Scene or an asperity::Error; no crash, no sanitizer report, no slow input.
#include <cstddef>
#include <cstdint>
#include <string>

#include "asperity/error.hpp"
#include "asperity/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const asperity::Scene scene = asperity::parse_scene(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
    (void)scene;
  } catch (const asperity::Error&) {
  }
  return 0;
}
