// The FE card's options, one implementation for `asperity contact --export` (the law's card) and
// `asperity exact-contact --card` (a measured map's exact curve): --max-points' default,
// --overclosure-datum's names, --face-size's check and CalculiX's contact-spring cut-off.
#pragma once
#include <CLI/CLI.hpp>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "asperity/pressure_overclosure.hpp"

namespace asperity::cli {

// --max-points: the cap asked (0: not given), else the format's: CalculiX's node-to-surface
// contact holds 200 points (calculix_points_max); no cap for Abaqus and CSV.
std::size_t card_max_points(long long asked, CardFormat format);

// --overclosure-datum's value (empty: zero-pressure, the default: the card starts at the surfaces
// touching, so that every mesh sees all of it); a usage error names the datums.
OverclosureDatum overclosure_datum_option(const std::string& text);

// --face-size L (the card's option `card`, e.g. "with --export calculix", begins its help), in
// `group`.
CLI::Option* add_face_size_option(CLI::App& command, double& face_size, const std::string& card,
                                  const std::string& group);

// --face-size: a positive length in the card's units (m, or mm with --units mm), with a CalculiX
// card (`card_option`: the option that writes one). Returns it in metres (NaN: not given).
double face_size_option(double face_size, CardFormat format, CardUnits units, const std::string& card_option);

// CalculiX's node-to-surface contact makes no spring beyond a clearance of 1e-3 sqrt(A): warns
// what of the card (rows in SI) never acts for faces of edge `face_size` [m] (NaN: not given, a
// note asks for it where the card has a clearance); `remedy` ends the warning ("use ...").
void check_spring_cutoff(const CLI::App& command, const std::vector<PressureOverclosurePoint>& rows, double face_size,
                         CardUnits units, const std::string& remedy);

}  // namespace asperity::cli
