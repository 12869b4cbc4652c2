// Written for slamsweep (not slam_toolbox code). slam_toolbox's Ceres solver asks Ceres for 50 threads
// (options_.num_threads in solvers/ceres_solver.cpp). With several threads Ceres sums the cost and gradient of
// each thread's share of the residuals, and which residuals a thread gets varies from run to run, so the sums,
// the accepted steps and with them the poses can differ between two runs of one input. The library is linked
// with --wrap for the symbol below: each of the solver's calls of ceres::Solve comes here and runs with the
// solver's options on one thread. The solver's file stays as upstream wrote it.
#include <ceres/problem.h>
#include <ceres/solver.h>

// ceres::Solve(const Solver::Options&, Problem*, Solver::Summary*) by its linker name, before and after the wrap.
extern "C" void __real__ZN5ceres5SolveERKNS_6Solver7OptionsEPNS_7ProblemEPNS0_7SummaryE(
    const ceres::Solver::Options& options, ceres::Problem* problem, ceres::Solver::Summary* summary);

extern "C" void __wrap__ZN5ceres5SolveERKNS_6Solver7OptionsEPNS_7ProblemEPNS0_7SummaryE(
    const ceres::Solver::Options& options, ceres::Problem* problem, ceres::Solver::Summary* summary) {
  ceres::Solver::Options one_thread = options;
  one_thread.num_threads = 1;
  __real__ZN5ceres5SolveERKNS_6Solver7OptionsEPNS_7ProblemEPNS0_7SummaryE(one_thread, problem, summary);
}
