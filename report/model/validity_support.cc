#include "report/model/validity_support.h"

#include <algorithm>
#include <array>
#include <optional>

#include <fmt/format.h>

namespace slamsweep::report::inline model {

namespace ev = slamsweep::evaluator;

namespace {

// The most independent error first: the corrected logs' ATE measures agreement with GMapping.
constexpr std::array<std::string_view, 3> kTargetPreference = {"relations_trans.mean", "ape_trans.rmse",
                                                               "map_chamfer.value"};

std::string TitleOf(std::string_view key) {
  const ev::ValidityQuantity* quantity = ev::FindValidityQuantity(key);
  return quantity ? std::string(quantity->title) : std::string(key);
}

/// The within-noise correlation the verdict rests on: the first preferred target with enough runs,
/// else the first one present (whose verdict then says "too few runs").
const ev::ValidityCorrelation* Deciding(const ev::ValidityStudy& study, std::string_view candidate,
                                        std::string_view scope) {
  const ev::ValidityCorrelation* first = nullptr;
  for (std::string_view target : kTargetPreference) {
    const ev::ValidityCorrelation* c = study.Find(candidate, target, scope, ev::ValidityPooling::kWithinNoise);
    if (!c) continue;
    if (!first) first = c;
    if (c->verdict != ev::ValidityVerdict::kTooFewRuns) return c;
  }
  return first;
}

std::string Evidence(const ev::ValidityCorrelation& c, const ev::ValidityStudy& study) {
  std::string text = fmt::format("{} within noise settings against the {}, {} runs", ev::ValidityVerdictName(c.verdict),
                                 TitleOf(c.target), c.runs);
  if (c.verdict == ev::ValidityVerdict::kTooFewRuns) text += fmt::format(" (fewer than {})", study.options.min_runs);
  if (c.rho) text += fmt::format(", Spearman's rho {:.2f}", *c.rho);
  if (c.interval) {
    text += fmt::format(", {:.0f} % interval [{:.2f}, {:.2f}]", 100.0 * study.options.bootstrap.confidence,
                        c.interval->low, c.interval->high);
  }
  return text;
}

ValiditySupport FromCorrelation(const ev::ValidityCorrelation* c, const ev::ValidityStudy& study,
                                std::string_view candidate, const std::string& where) {
  if (c && c->verdict == ev::ValidityVerdict::kTracksError) return {true, {}};
  if (!c)
    return {false, fmt::format("{}: not marked best: the validity study of {} has no correlation for it",
                               TitleOf(candidate), where)};
  return {false,
          fmt::format("{}: not marked best: the validity study of {} does not show that it tracks the error ({})",
                      TitleOf(candidate), where, Evidence(*c, study))};
}

/// The study's scope standing in for a sequence it does not cover: all its sequences pooled, or its only one.
std::string StandInScope(const ev::ValidityStudy& study) {
  return study.sequences.size() == 1 ? study.sequences.front() : std::string();
}

}  // namespace

ValiditySupport SupportFor(std::string_view candidate, std::string_view sequence, const ev::ValidityStudy& own,
                           const ev::ValidityStudy* named, std::string_view named_source) {
  if (std::find(own.sequences.begin(), own.sequences.end(), sequence) != own.sequences.end()) {
    return FromCorrelation(Deciding(own, candidate, sequence), own, candidate, "this sequence");
  }
  // No reference here: the sweep's own study of its other sequences, unless it has too few runs to
  // say anything; then a study the sweep names.
  std::optional<ValiditySupport> from_own;
  if (!own.empty()) {
    const std::string scope = StandInScope(own);
    const std::string where =
        (scope.empty() ? "this sweep's " + std::to_string(own.sequences.size()) + " sequences with a reference (pooled)"
                       : "this sweep's sequence " + scope) +
        ", as this one has no reference";
    const ev::ValidityCorrelation* c = Deciding(own, candidate, scope);
    from_own = FromCorrelation(c, own, candidate, where);
    if (c && c->verdict != ev::ValidityVerdict::kTooFewRuns) return *from_own;
  }
  if (named && !named->empty()) {
    const std::string scope = StandInScope(*named);
    return FromCorrelation(Deciding(*named, candidate, scope), *named, candidate,
                           "the named study " + std::string(named_source) + ", as this sequence has no reference");
  }
  if (from_own) return *from_own;
  return {false, fmt::format("{}: not marked best: no sequence of this sweep has a reference, so no validity study "
                             "shows that it tracks the error (name one with validity_study: in the sweep file)",
                             TitleOf(candidate))};
}

}  // namespace slamsweep::report::inline model
