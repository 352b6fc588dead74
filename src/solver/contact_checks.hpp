#pragma once
// Start-up checks of a *CONTACT that do not stop the run but deserve a word to the user
// (issue 13): the warnings of its ContactReport.
#include <string>
#include <vector>

#include "abut/solver/contact_report.hpp"
#include "abut/solver/model.hpp"

namespace abut {

// A pair of deformable parts whose automatic penalties differ by more than this factor: the
// pair runs with the smaller one (seed 000), an order of magnitude softer than the stiffer side's
// own.
inline constexpr double kGovernedPenaltyRatio = 10.0;

// One warning per such pair of the report (parts and pairs filled in), naming both parts.
std::vector<std::string> penalty_warnings(const Model& model, const ContactReport& report);

}  // namespace abut
