// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Why Active_set_box_QP_solver keeps its own sparse factorisation: internal::Supernodal_LDLT
// ("ours") against Eigen::SimplicialLDLT with Eigen::AMDOrdering ("eigen_simplicial") and, when
// CMake found CHOLMOD, CHOLMOD's supernodal Cholesky through Eigen::CholmodSupernodalLLT
// ("cholmod_supernodal", AMD ordering as the others), on the matrices the fairing factorises:
// the bi-Laplacian plus highlight-node terms of fairing_like_programs.h (the generator of
// benchmark_qp_solver.cpp), n = 10^3, 10^4, 10^5 variables, a random right-hand side; and the
// fairing's default programs, whose curvature-variation term couples the vertices within three
// edges ("rings:3"; n = 10^4, 10^5), where the QP solver also tries a nested dissection
// ordering (internal/qp/fill_reducing_ordering.h): "ours_nested_dissection" is our
// factorisation in METIS's ordering, present where the benchmark links METIS (as the QP solver
// does, through CGAL::METIS_support), and "x ours" compares it with ours in AMD's ordering.
//
//   benchmark_factorization [Google Benchmark options]   timings and counters, then the table
//   benchmark_factorization --table                       each phase timed alone, the table only
//
// e.g. one case, medians of three:  benchmark_factorization --benchmark_filter='n:10000/rings:2'
//        --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// Benchmarks <phase>/<solver>/n:<n>/rings:<2 or 3>:
//   analysis       fill-reducing ordering + symbolic factorisation;
//   factorization  the numeric factorisation alone, on a pattern analysed once (the fairing
//                  refactorises the same pattern at each of its iterations);
//   solve          one solve with the factor.
// Counters: n; flops, the flops of a factorisation counted by the analysis (ours only);
// factor_nnz, the entries of the factor L, diagonal included (ours: the entries of
// its supernodal panels, with the explicit zeros of amalgamated supernodes and of the upper
// halves of the dense diagonal blocks; Eigen: nnz(L) + n; CHOLMOD: Common.lnz, without
// amalgamation zeros); x_ours, the time over ours of the same phase and size earlier in the
// same run; residual, |A x - b| / |b| after a solve: above 1e-8 the benchmark reports an error.
// The table gives the medians over the runs.
//
// One thread: Eigen::setNbThreads(1); CHOLMOD and its BLAS by OMP_THREAD_LIMIT=1,
// OMP_NUM_THREADS=1 and OPENBLAS_NUM_THREADS=1 (see main()). The CPU column is the process's CPU
// time: equal to the wall time when a single thread works.

#include <CGAL/Highlight_lines/Active_set_box_QP_solver.h>
#include <CGAL/Highlight_lines/internal/qp/fill_reducing_ordering.h>

#include "fairing_like_programs.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#ifdef HIGHLIGHT_LINES_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#include <unistd.h> // execv
#endif
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

using Fairness = Highlight_lines_benchmark::Fairing_like_patch::Fairness;

// The cases: n and the rings the program couples (2: bi-Laplacian, 3: curvature variation).
const std::pair<int, int> cases[] = {{1000, 2}, {10000, 2}, {100000, 2}, {10000, 3}, {100000, 3}};
const double largest_residual = 1e-8;

// ---------------------------------------------------------------------------------------------
// The factorisations, behind one interface: analyze(A), factorize(A) (false on failure),
// solve(b, x), factor_nonzeros(). A holds both triangles, as the QP solver's P.

// Called as Active_set_box_QP_solver::update_analysis() and factorize() call it when every
// variable is free (then the values it factorises are P's own, in P's pattern), in one
// ordering: AMD ("ours") or nested dissection ("ours_nested_dissection").
template <CGAL::Highlight_lines::internal::Ordering_method method>
class Ours_in_ordering
{
public:
  static constexpr const char* name =
      method == CGAL::Highlight_lines::internal::Ordering_method::MINIMUM_DEGREE
          ? "ours"
          : "ours_nested_dissection";

  void analyze(const Sparse_matrix& A)
  {
    n_ = static_cast<int>(A.cols());
    // The solver keeps its own copy of the whole pattern.
    outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + n_ + 1);
    inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
    ordering_ = CGAL::Highlight_lines::internal::fill_reducing_ordering(A, method);
    ldlt_.analyze(n_, outer_.data(), inner_.data(), ordering_);
  }
  bool factorize(const Sparse_matrix& A)
  {
    return ldlt_.factorize(A.valuePtr(), pivot_tolerance_) ==
           CGAL::Highlight_lines::internal::Supernodal_LDLT::Inertia::POSITIVE_DEFINITE;
  }
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const
  {
    x = b;
    ldlt_.solve(x);
  }
  // Supernodal_LDLT::analyze() counts 4 solve flops per stored entry of L and 4 per variable.
  double factor_nonzeros() const { return (ldlt_.solve_flops() - 4. * n_) / 4.; }
  double factorization_flops() const { return ldlt_.factorization_flops(); }

private:
  const double pivot_tolerance_ =
      CGAL::Highlight_lines::Active_set_box_QP_solver().pivot_tolerance();
  int n_ = 0;
  std::vector<int> outer_, inner_, ordering_;
  CGAL::Highlight_lines::internal::Supernodal_LDLT ldlt_;
};

using Ours = Ours_in_ordering<CGAL::Highlight_lines::internal::Ordering_method::MINIMUM_DEGREE>;
using Ours_nested_dissection =
    Ours_in_ordering<CGAL::Highlight_lines::internal::Ordering_method::NESTED_DISSECTION>;

class Eigen_simplicial
{
public:
  static constexpr const char* name = "eigen_simplicial";

  void analyze(const Sparse_matrix& A) { ldlt_.analyzePattern(A); }
  bool factorize(const Sparse_matrix& A)
  {
    ldlt_.factorize(A);
    return ldlt_.info() == Eigen::Success;
  }
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const { x = ldlt_.solve(b); }
  // Eigen's LDL^T stores the strictly lower part of the unit L.
  double factor_nonzeros() const
  {
    return static_cast<double>(ldlt_.matrixL().nestedExpression().nonZeros() + ldlt_.rows());
  }
  double factorization_flops() const { return -1.; } // not counted

private:
  Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
};

#ifdef HIGHLIGHT_LINES_HAVE_CHOLMOD
class Cholmod_supernodal
{
public:
  static constexpr const char* name = "cholmod_supernodal";

  // AMD only, as the others: by default CHOLMOD may also try METIS, and then the comparison
  // would measure the orderings rather than the factorisations.
  Cholmod_supernodal()
  {
    llt_.cholmod().nmethods = 1;
    llt_.cholmod().method[0].ordering = CHOLMOD_AMD;
    llt_.cholmod().postorder = 1;
  }
  void analyze(const Sparse_matrix& A) { llt_.analyzePattern(A); }
  bool factorize(const Sparse_matrix& A)
  {
    llt_.factorize(A);
    return llt_.info() == Eigen::Success;
  }
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const { x = llt_.solve(b); }
  double factor_nonzeros() const { return llt_.cholmod().lnz; }
  double factorization_flops() const { return -1.; } // not counted

private:
  mutable Eigen::CholmodSupernodalLLT<Sparse_matrix, Eigen::Lower> llt_; // cholmod() is not const
};
#endif

// ---------------------------------------------------------------------------------------------
// Cases, phases, results

struct Case
{
  Highlight_lines_benchmark::Fairing_like_patch patch;
  Eigen::VectorXd b;

  Case(int n, int rings)
      : patch(n, rings == 3 ? Fairness::CURVATURE_VARIATION : Fairness::BI_LAPLACIAN), b(n)
  {
    std::mt19937 random(4242u + static_cast<unsigned>(n));
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (int i = 0; i < n; ++i)
      b[i] = uniform(random);
  }
  const Sparse_matrix& A() const { return patch.Q; }
};

// A patch of 10^5 vertices takes seconds to build: shared by all benchmarks of its case.
const Case& get_case(int n, int rings)
{
  static std::map<std::pair<int, int>, Case> cache;
  return cache.try_emplace({n, rings}, n, rings).first->second;
}

enum Phase { ANALYSIS, FACTORIZATION, SOLVE };
const char* const phase_names[] = {"analysis", "factorization", "solve"};

struct Run
{
  double seconds = 0., calls = 0.;
};

struct Result
{
  std::vector<Run> runs;
  double factor_nonzeros = 0., factorization_flops = -1., residual = 0.;

  // The median time per call. Google Benchmark first runs a case with fewer iterations to
  // choose their number: the runs with the most calls are the measured ones.
  double seconds() const
  {
    double most_calls = 0.;
    for (const Run& run : runs)
      most_calls = std::max(most_calls, run.calls);
    std::vector<double> times;
    for (const Run& run : runs)
      if (run.calls == most_calls)
        times.push_back(run.seconds / run.calls);
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    return times[times.size() / 2]; // of an odd number of runs, as the table's and Google's
  }
};

std::map<std::tuple<int, int, std::string, int>, Result> results; // [{n, rings, solver, phase}]

// The matrices are positive definite: a failed factorisation is a bug.
void require(bool factorized, const char* solver)
{
  if (!factorized)
    throw std::runtime_error(std::string(solver) + ": the factorisation failed");
}

// Measures `phase` of a new Factorization (the phases before it done once, untimed):
// repeat(call) calls `call`, which runs the phase once and returns its seconds, as often as it
// wants. Then checks a solve's residual, untimed, and records the run.
template <typename Factorization, typename Repeat>
const Result& measure(int n, int rings, Phase phase, Repeat&& repeat)
{
  const Case& c = get_case(n, rings);
  Factorization f;
  if (phase != ANALYSIS)
    f.analyze(c.A());
  if (phase == SOLVE)
    require(f.factorize(c.A()), Factorization::name);
  Eigen::VectorXd x;
  Run run;
  repeat([&] {
    const auto begin = std::chrono::steady_clock::now();
    bool factorized = true;
    if (phase == ANALYSIS)
      f.analyze(c.A());
    else if (phase == FACTORIZATION)
      factorized = f.factorize(c.A());
    else
      f.solve(c.b, x);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    require(factorized, Factorization::name);
    run.seconds += seconds;
    run.calls += 1.;
    return seconds;
  });

  Result& result = results[{n, rings, Factorization::name, phase}];
  result.runs.push_back(run);
  if (phase == ANALYSIS)
    require(f.factorize(c.A()), Factorization::name);
  f.solve(c.b, x);
  result.residual = (c.A() * x - c.b).norm() / c.b.norm();
  result.factor_nonzeros = f.factor_nonzeros();
  result.factorization_flops = f.factorization_flops();
  return result;
}

// ---------------------------------------------------------------------------------------------
// Google Benchmark and the table

template <typename Factorization>
void BM_phase(benchmark::State& state, Phase phase)
{
  const int n = static_cast<int>(state.range(0)), rings = static_cast<int>(state.range(1));
  const Result& result = measure<Factorization>(n, rings, phase, [&](auto&& call) {
    for (auto _ : state)
      call();
  });
  state.counters["n"] = n;
  if (result.factorization_flops >= 0.)
    state.counters["flops"] = result.factorization_flops;
  state.counters["factor_nnz"] = result.factor_nonzeros;
  state.counters["residual"] = result.residual;
  const auto ours = results.find({n, rings, Ours::name, phase});
  if (ours != results.end())
    state.counters["x_ours"] =
        result.runs.back().seconds / result.runs.back().calls / ours->second.seconds();
  if (!(result.residual < largest_residual))
    state.SkipWithError("residual |Ax - b| / |b| above 1e-8");
}

template <typename Factorization>
void register_phase(int n, int rings, Phase phase)
{
  const std::string name = std::string(phase_names[phase]) + "/" + Factorization::name;
  benchmark::RegisterBenchmark(name.c_str(), BM_phase<Factorization>, phase)
      ->Args({n, rings})
      ->ArgNames({"n", "rings"})
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->MeasureProcessCPUTime();
}

// Without Google Benchmark: five runs of each phase, each of as many calls as the first run
// made in 0.2 s (at least one).
template <typename Factorization>
void table_runs(int n, int rings)
{
  for (Phase phase : {ANALYSIS, FACTORIZATION, SOLVE}) {
    int calls = 0;
    for (int run = 0; run < 5; ++run)
      measure<Factorization>(n, rings, phase, [&](auto&& call) {
        for (double seconds = 0.; run == 0 && seconds < 0.2; ++calls)
          seconds += call();
        for (int k = 0; run > 0 && k < calls; ++k)
          call();
      });
  }
}

template <typename... Factorizations>
struct Compared
{
  static std::vector<std::string> names() { return {Factorizations::name...}; }
  static void register_all(int n, int rings, Phase phase)
  {
    (register_phase<Factorizations>(n, rings, phase), ...);
  }
  static void run_for_table(int n, int rings) { (table_runs<Factorizations>(n, rings), ...); }
};
// Nested dissection needs METIS: without it, fill_reducing_ordering() would give AMD again.
#if defined(CGAL_METIS_ENABLED) && defined(HIGHLIGHT_LINES_HAVE_CHOLMOD)
using Solvers = Compared<Ours, Ours_nested_dissection, Eigen_simplicial, Cholmod_supernodal>;
#elif defined(CGAL_METIS_ENABLED)
using Solvers = Compared<Ours, Ours_nested_dissection, Eigen_simplicial>;
#elif defined(HIGHLIGHT_LINES_HAVE_CHOLMOD)
using Solvers = Compared<Ours, Eigen_simplicial, Cholmod_supernodal>;
#else
using Solvers = Compared<Ours, Eigen_simplicial>;
#endif

void print_table(std::ostream& out)
{
  char line[256];
  for (const auto& [n, rings] : cases) {
    const auto first = results.lower_bound({n, rings, std::string(), 0});
    if (first == results.end() || std::get<0>(first->first) != n ||
        std::get<1>(first->first) != rings)
      continue;
    out << "\nn = " << n << ", coupled within " << rings
        << " edges, nnz(A) = " << get_case(n, rings).A().nonZeros() << " (both triangles)\n";
    std::snprintf(line, sizeof line, "  %-22s %11s %7s %11s %7s %11s %7s %11s %9s %9s\n", "",
                  "analysis ms", "x ours", "factor. ms", "x ours", "solve ms", "x ours",
                  "factor nnz", "GFlop", "residual");
    out << line;
    for (const std::string& solver : Solvers::names()) {
      std::string cells;
      double factor_nonzeros = -1., flops = -1., residual = 0.;
      for (int phase : {ANALYSIS, FACTORIZATION, SOLVE}) {
        const auto it = results.find({n, rings, solver, phase});
        const auto ours = results.find({n, rings, Ours::name, phase});
        char time[32] = "-", ratio[32] = "-";
        if (it != results.end()) {
          std::snprintf(time, sizeof time, "%.3f", 1e3 * it->second.seconds());
          if (ours != results.end())
            std::snprintf(ratio, sizeof ratio, "%.2f",
                          it->second.seconds() / ours->second.seconds());
          factor_nonzeros = it->second.factor_nonzeros;
          flops = it->second.factorization_flops;
          residual = std::max(residual, it->second.residual);
        }
        std::snprintf(line, sizeof line, " %11s %7s", time, ratio);
        cells += line;
      }
      if (factor_nonzeros < 0.)
        continue;
      char gigaflops[32] = "-";
      if (flops >= 0.)
        std::snprintf(gigaflops, sizeof gigaflops, "%.3g", 1e-9 * flops);
      std::snprintf(line, sizeof line, "  %-22s%s %11.0f %9s %9.1e%s\n", solver.c_str(),
                    cells.c_str(), factor_nonzeros, gigaflops, residual,
                    residual < largest_residual ? "" : " (!)");
      out << line;
    }
  }
  out << "\n  (medians over the runs; x ours: time / ours' of the same phase; factor nnz: entries "
         "of L with its diagonal, ours with its supernodal panels' explicit zeros; GFlop: a "
         "factorisation's flops counted by our analysis; residual: the largest |Ax - b| / |b| of "
         "the solves checked, (!) above 1e-8)\n";
}

#ifdef HIGHLIGHT_LINES_HAVE_CHOLMOD
// CHOLMOD's supernodal factorisation opens OpenMP regions with num_threads(4), which
// OMP_NUM_THREADS does not lower; OMP_THREAD_LIMIT does, but the OpenMP runtime reads it when
// the program is loaded, as a threaded BLAS reads its own variable: set them and start again.
void restart_on_one_thread(char** argv)
{
  const char* limit = std::getenv("OMP_THREAD_LIMIT");
  if (limit && std::strcmp(limit, "1") == 0)
    return;
  setenv("OMP_THREAD_LIMIT", "1", 1);
  setenv("OMP_NUM_THREADS", "1", 1);
  setenv("OPENBLAS_NUM_THREADS", "1", 1);
  setenv("MKL_NUM_THREADS", "1", 1);
  execv("/proc/self/exe", argv);
  std::cerr << "benchmark_factorization: could not restart with OMP_THREAD_LIMIT=1, CHOLMOD may "
               "use several threads\n";
}
#endif

} // namespace

int main(int argc, char** argv)
{
#ifdef HIGHLIGHT_LINES_HAVE_CHOLMOD
  restart_on_one_thread(argv);
#endif
  Eigen::setNbThreads(1);
  bool table = false;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--table") == 0)
      table = true;
    else
      args.push_back(argv[i]);
  }
  try {
    if (table) {
      for (const auto& [n, rings] : cases)
        Solvers::run_for_table(n, rings);
      print_table(std::cout);
      return 0;
    }
    // Ours first in each phase and size: the others' x_ours counters read its time.
    for (const auto& [n, rings] : cases)
      for (Phase phase : {ANALYSIS, FACTORIZATION, SOLVE})
        Solvers::register_all(n, rings, phase);
    int count = static_cast<int>(args.size());
    benchmark::Initialize(&count, args.data());
    if (benchmark::ReportUnrecognizedArguments(count, args.data()))
      return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    print_table(std::cout);
  } catch (const std::exception& e) {
    std::cerr << "benchmark_factorization: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
