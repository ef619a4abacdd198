#include "asperity/topography/exact_contact_report.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "record_json.hpp"

namespace asperity::topography {

std::string exact_contact_json(const HeightMap& map, bool leveled, const ExactContact& solver,
                               const ExactContactOptions& options, bool by_pressure,
                               const std::vector<ContactStep>& steps) {
  using nlohmann::json;
  json steps_json = json::array();
  for (const ContactStep& step : steps) steps_json.push_back(record_json(step));
  const double mean_summit_height = solver.mean_summit_height();
  const json document = {
      {"schema", exact_contact_json_schema},
      {"map",
       {{"source", map.source},
        {"nx", map.nx},
        {"ny", map.ny},
        {"dx_m", map.dx},
        {"dy_m", map.dy},
        {"missing_points", map.missing_points()},
        {"leveled", leveled},
        {"rms_height_m", solver.rms_height()},
        {"max_height_m", solver.max_height()},
        {"summits", solver.summits()},
        {"mean_summit_height_m", std::isfinite(mean_summit_height) ? json(mean_summit_height) : json(nullptr)},
        {"nominal_area_m2", solver.nominal_area()}}},
      {"solver",
       {{"contact_modulus_Pa", options.contact_modulus},
        {"boundary", contact_boundary_name(options.boundary)},
        {"kernel", contact_kernel_name(options.kernel)},
        {"algorithm", contact_solver_name(options.solver)},
        {"coarse_start", options.coarse_start},
        {"tolerance", options.tolerance},
        {"hardness_Pa", is_plastic(options) ? json(options.hardness) : json(nullptr)},
        {"work_of_adhesion_J_per_m2", is_adhesive(options) ? json(options.work_of_adhesion) : json(nullptr)},
        {"adhesive_stress_Pa", is_adhesive(options) ? json(options.adhesive_stress) : json(nullptr)},
        {"driven_by", by_pressure ? "pressure" : "mean_gap"}}},
      {"steps", steps_json}};
  return document.dump(2, ' ', false, json::error_handler_t::replace);
}

}  // namespace asperity::topography
