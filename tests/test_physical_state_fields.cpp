// The physical state's fields are defined once (asperity/physical_state_fields.hpp); the files
// that cannot be made from that list (the C header, the Fortran module, the Python stubs) are
// read here and their field names, in order, compared with it. The C API also checks its struct
// at compile time (offsetof, runtime/c_api/c_api.cpp); PhysicalState and the writers are made
// from the list.
#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/contact_model.hpp"
#include "asperity/physical_state_fields.hpp"

namespace {

std::string read(const std::string& relative) {
  std::ifstream in(std::string(ASPERITY_SOURCE_DIR) + "/" + relative);
  EXPECT_TRUE(in) << "cannot read " << relative;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text between `start` (its first occurrence) and the first `end` after it
std::string block(const std::string& text, const std::string& start, const std::string& end) {
  const std::size_t from = text.find(start);
  if (from == std::string::npos) return "";
  const std::size_t to = text.find(end, from + start.size());
  return text.substr(from + start.size(), to == std::string::npos ? std::string::npos : to - from - start.size());
}

// Every first capture of `field` in `text`, in order
std::vector<std::string> names(const std::string& text, const std::regex& field) {
  std::vector<std::string> out;
  for (std::sregex_iterator it(text.begin(), text.end(), field), end; it != end; ++it) out.push_back((*it)[1]);
  return out;
}

std::vector<std::string> list() {
  std::vector<std::string> out;
  for (const asperity::PhysicalStateField& field : asperity::physical_state_fields) out.push_back(field.name);
  return out;
}

TEST(PhysicalStateFields, TheListIsThePhysicalState) {
  ASSERT_EQ(asperity::physical_state_field_count, 9u);
  EXPECT_EQ(sizeof(asperity::PhysicalState), asperity::physical_state_field_count * sizeof(double));
  asperity::PhysicalState state{};
  for (std::size_t k = 0; k < asperity::physical_state_field_count; ++k) state.*asperity::physical_state_members[k] = k;
  EXPECT_EQ(state.separation, 0);
  EXPECT_EQ(state.count, 2);
  EXPECT_EQ(state.stiffness_over_load, 8);
  for (const asperity::PhysicalStateField& field : asperity::physical_state_fields) {
    EXPECT_TRUE(std::regex_match(field.name, std::regex("[a-z_]+"))) << field.name;
    EXPECT_TRUE(std::regex_match(field.column, std::regex("[A-Za-z0-9_]+"))) << field.column;
    EXPECT_NE(std::string(field.meaning), "");
  }
}

TEST(PhysicalStateFields, TheCHeaderHasTheListsFieldsInOrder) {
  const std::string c = block(read("include/asperity/asperity.h"), "typedef struct asperity_physical_state {", "}");
  EXPECT_EQ(names(c, std::regex(R"(double\s+([a-z_]+)\s*;)")), list());
}

TEST(PhysicalStateFields, TheFortranModuleHasTheListsFieldsInOrder) {
  const std::string f =
      block(read("include/asperity/asperity.f90"), "type, bind(c), public :: asperity_physical_state", "end type");
  EXPECT_EQ(names(f, std::regex(R"(real\(c_double\)\s*::\s*([a-z_]+))")), list());
}

TEST(PhysicalStateFields, ThePythonStubsHaveTheListsFieldsInOrder) {
  const std::string py = block(read("python/asperity/__init__.pyi"), "class PhysicalState(NamedTuple):", "\n\n");
  EXPECT_EQ(names(py, std::regex(R"(\n    ([a-z_]+):)")), list());
}

}  // namespace
