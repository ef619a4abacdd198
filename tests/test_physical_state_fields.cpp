// The result records are defined once, each by its list (asperity/record_fields.hpp): the physical
// state (physical_state_fields.hpp), ContactState (contact.hpp), ContactCurvesState
// (contact_curves.hpp), the topography's ContactStep and PerssonState. The files that cannot be
// made from those lists (the C header, the Fortran module, the Python stubs) are read here and
// their field names, in order, compared with them. The C API also checks its structs at compile
// time (offsetof, runtime/c_api/c_api.cpp); the structs and the writers are made from the lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/contact.hpp"
#include "asperity/contact_curves.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/physical_state_fields.hpp"
#include "asperity/record_fields.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/persson_contact.hpp"

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

// A record's member names, from its list
template <class Record>
std::vector<std::string> record_names() {
  std::vector<std::string> out;
  for (const asperity::RecordField& field : asperity::RecordFields<Record>::fields) out.push_back(field.name);
  return out;
}

// The names a C struct declares (`double a, b;` or one a line), comments left out
std::vector<std::string> c_members(const std::string& header, const std::string& struct_name) {
  std::string text = block(read(header), "typedef struct " + struct_name + " {", "}");
  text = std::regex_replace(text, std::regex(R"(/\*[^*]*\*/)"), "");
  std::vector<std::string> out;
  for (const std::string& declaration : names(text, std::regex(R"((?:double|int|size_t)\s+([^;]+);)")))
    for (const std::string& name : names(declaration, std::regex(R"(([a-z_]+))"))) out.push_back(name);
  return out;
}

// The names a Fortran bind(c) type declares (`real(c_double) :: a, b` or one a line), comments left out
std::vector<std::string> fortran_members(const std::string& type_name) {
  const std::string text = block(read("include/asperity/asperity.f90"), "type, bind(c), public :: " + type_name, "end type");
  std::vector<std::string> out;
  for (const std::string& names_part : names(text, std::regex(R"(::\s*([a-z_, ]+))")))
    for (const std::string& name : names(names_part, std::regex(R"(([a-z_]+))"))) out.push_back(name);
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

// The other records with a C, Fortran or Python twin
TEST(RecordFields, TheContactStatesTwinsHaveTheListsFieldsInOrder) {
  EXPECT_EQ(asperity::RecordFields<asperity::ContactState>::count, 5u);
  EXPECT_EQ(sizeof(asperity::ContactState), 5 * sizeof(double));
  EXPECT_EQ(c_members("include/asperity/asperity.h", "asperity_contact_state"), record_names<asperity::ContactState>());
  EXPECT_EQ(fortran_members("asperity_contact_state"), record_names<asperity::ContactState>());
  const std::string py = block(read("python/asperity/__init__.pyi"), "class ContactState(NamedTuple):", "\n\n");
  EXPECT_EQ(names(py, std::regex(R"(\n    ([a-z_]+):)")), record_names<asperity::ContactState>());
}

TEST(RecordFields, TheContactCurvesStatesTwinsHaveTheListsFieldsInOrder) {
  EXPECT_EQ(sizeof(asperity::ContactCurvesState), 4 * sizeof(double));
  EXPECT_EQ(c_members("include/asperity/asperity.h", "asperity_contact_curves_state"),
            record_names<asperity::ContactCurvesState>());
  EXPECT_EQ(fortran_members("asperity_contact_curves_state"), record_names<asperity::ContactCurvesState>());
}

TEST(RecordFields, TheTopographysRecordsStubsHaveTheListsFields) {
  const std::string stubs = read("python/asperity/topography.pyi");
  const std::string step = block(stubs, "class ContactStep:", "\n\n");
  EXPECT_EQ(names(step, std::regex(R"(\n    ([a-z_]+):)")), record_names<asperity::topography::ContactStep>());
  const std::string persson = block(stubs, "class PerssonState:", "\n\n");
  EXPECT_EQ(names(persson, std::regex(R"(def ([a-z_]+)\(self\))")), record_names<asperity::topography::PerssonState>());
}

// The writers: columns of written fields only, in order; integers in decimal
TEST(RecordFields, TheCsvIsMadeFromTheList) {
  using asperity::topography::ContactStep;
  const std::string header = asperity::csv_header<ContactStep>();
  EXPECT_EQ(header.find("coarse_iterations"), std::string::npos);
  EXPECT_EQ(header.rfind("pressure_Pa,load_N,mean_gap_m,", 0), 0u);
  ContactStep step;
  step.pressure = 1.5;
  step.contact_points = 12;
  step.iterations = 7;
  step.coarse_iterations = 99;
  const std::string row = asperity::csv_row(step);
  EXPECT_EQ(std::count(row.begin(), row.end(), ','), std::count(header.begin(), header.end(), ','));
  EXPECT_EQ(row.rfind("1.5,0,0,0,0,0,0,12,0,", 0), 0u);
  EXPECT_EQ(row.find("99"), std::string::npos);
  EXPECT_EQ(asperity::csv_header<asperity::PhysicalState>().rfind("separation_m,mean_separation_m,count,", 0), 0u);
}

}  // namespace
