// cli/figures_bench.cpp -- the toolbox's speed-against-accuracy charts, one per bench/ program,
// registered with `hapstab figure` / `hapstab reproduce`. Their data comes from running the
// Google Benchmark program (bench/chart-NAME, see bench/README.md); an installed hapstab without
// the bench programs reports them "not reproduced" instead of failing.
#include "cli/figure.hpp"

namespace hapstab::cli {
namespace {

const RegisterFigure sampling({"sampling_speed_accuracy", "toolbox",
                               "r(jw) (paper 001): time per evaluation against relative error for every closed form "
                               "and scalar, the truncated series (34), the accelerated series and the certified "
                               "enclosure; and each double form's error over wT in [1e-8, pi]",
                               [](const std::filesystem::path& d) { write_bench_chart_data("sampling", d); },
                               [](const std::filesystem::path& d) { return bench_timing_vars("sampling", d); }});
const RegisterFigure passivity({"passivity_speed_accuracy", "toolbox",
                                "Passivity bound b*: time per case against relative error for the fast path, the "
                                "certified method at 16/30/100 digits and N-point grids",
                                [](const std::filesystem::path& d) { write_bench_chart_data("passivity", d); },
                                [](const std::filesystem::path& d) { return bench_timing_vars("passivity", d); }});
const RegisterFigure contact({"contact_speed_accuracy", "toolbox",
                              "Wedge criterion: time per check against the margin's relative error (exact verdict "
                              "with certified margin against grids)",
                              [](const std::filesystem::path& d) { write_bench_chart_data("contact", d); },
                              [](const std::filesystem::path& d) { return bench_timing_vars("contact", d); }});
const RegisterFigure lmi({"lmi_scaling", "toolbox",
                          "LMI layer: solve + exact certificate time against problem size on Theorem 5's "
                          "structure, DSDP, CSDP and the built-in IPM",
                          [](const std::filesystem::path& d) { write_bench_chart_data("lmi", d); },
                          [](const std::filesystem::path& d) { return bench_timing_vars("lmi", d); }});
const RegisterFigure multidof({"multidof_scaling", "toolbox",
                               "Theorem 5 scaling: analysis time against total DOF and the fraction of random "
                               "environments certified stable, one operator (case i) against one per device (case ii); "
                               "the contact scenes' analysis and Theorem 6 design against N; the planned paths "
                               "(decomposed, KYP/Riccati, witness) beside the generic SDP and DSDP on several objects, "
                               "delays and infeasible scenes",
                               [](const std::filesystem::path& d) { write_bench_chart_data("multidof", d); },
                               [](const std::filesystem::path& d) { return bench_timing_vars("multidof", d); }});
const RegisterFigure sim({"sim_speed_accuracy", "toolbox",
                          "Simulator: steps per second against maximum relative error for exact ZOH, RK4 with n "
                          "substeps and adaptive Odeint on the same run",
                          [](const std::filesystem::path& d) { write_bench_chart_data("sim", d); },
                          [](const std::filesystem::path& d) { return bench_timing_vars("sim", d); }});

}  // namespace
}  // namespace hapstab::cli
