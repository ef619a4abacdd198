// The FE card's options, one implementation for `asperity contact --export` (the law's card) and
// `asperity exact-contact --card` (a measured map's exact curve): --max-points' default,
// --overclosure-datum's names, --face-size's check and CalculiX's contact-spring cut-off.
#pragma once
#include <CLI/CLI.hpp>
#include <cstddef>
#include <functional>
#include <string>

#include "asperity/pressure_overclosure.hpp"

namespace asperity::cli {

// --max-points: the cap asked (0: not given), else the format's: CalculiX's node-to-surface
// contact holds 200 points (calculix_points_max); no cap for Abaqus and CSV.
std::size_t card_max_points(long long asked, CardFormat format);

// --overclosure-datum's value (empty: mean-summit, the default); a usage error names the datums.
OverclosureDatum overclosure_datum_option(const std::string& text);

// --face-size: a positive length, with a CalculiX card (`card_option`: the option that writes one).
void check_face_size_option(double face_size, CardFormat format, const std::string& card_option);

// CalculiX's node-to-surface contact makes no spring beyond a clearance of 1e-3 sqrt(A): says
// what of a card reaching `clearance` [m] never acts for faces of edge `face_size` (NaN: not
// given, a note asks for it). pressure_at(clearance) is the card's pressure there [Pa];
// `remedy` ends the warning ("use ...").
void check_spring_cutoff(const CLI::App& command, double clearance, double face_size,
                         const std::function<double(double)>& pressure_at, const std::string& remedy);

}  // namespace asperity::cli
