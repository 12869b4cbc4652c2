#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace httplib {
struct Request;
}

namespace slamsweep::orchestrator::service {

struct ApiContext;

/// The answer to POST /api/sweeps.
struct SubmissionAnswer {
  int status = 500;
  nlohmann::json body;
  std::vector<std::pair<std::string, std::string>> headers;
};

/// Checks and queues a submitted sweep. Query: `priority` (whole number -100..100, default 0; higher
/// first), `name` (the sweep file's name as the submitter typed it: config messages name it) and `base`
/// (the absolute folder its relative paths are anchored at, default DATA/submitted). Header
/// X-Slamsweep-Submitter: who submits (shown on the page; default the client's address).
/// 201 with the sweep id and its planned run ids; 400 for a bad parameter or a config error (the message
/// `slamsweep plan` prints for the same file); 403 when the file reads outside the allowed roots or uses
/// the command adapter without --allow-commands; 413 for too many runs; 429 when too many sweeps are
/// queued; 503 while draining. Nothing is written unless the answer is 201.
SubmissionAnswer Submit(ApiContext& context, const httplib::Request& request);

}  // namespace slamsweep::orchestrator::service
