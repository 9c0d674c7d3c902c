// cli/multidof_certificate.hpp -- `multidof analyze --scene S --certificate FILE` (issue 47): the
// certificate of Theorem 5's program (16) proven feasible -- the exact point (P, X, Q_E, Q_V) on the
// realisation of E-hat it was checked on (check/multidof_feasible_check.hpp, kind multidof-feasible),
// or, for a scene of identical DOFs whose lifted point is above order 40, the split's block points
// (check/multidof_symmetric_check.hpp, kind multidof-feasible-symmetric) -- or infeasible by a
// frequency-domain witness, at one frequency or at several with weights
// (check/multidof_witness_check.hpp, kind multidof-witness), or by the facial conditions.
// `multidof design --certificate`: the designed coupling against Theorem 4 (kind multidof-coupling;
// designed on the split, multidof-coupling-symmetric).
// The model is the scene's as written: the environment's expressions (`tf`), domain, method and
// gain, the parameters, the delay, each device's OSP level (a mass-damper's b, or the declared
// `osp`) and the operators' DOFs (and the designed V).
// Where (16) is proven feasible but Assumption 1(b) fails for an operator given by `tf` (paper 000
// case i's H1), Theorem 5 concludes nothing: `--premise-certificate FILE` writes the reason, the
// operator's negative principal minor of He Z(jw) (check/operator_passivity_check.hpp, kind
// operator-passivity; the model the scene's text). Other verdicts have no multi-DOF kind yet (the loop as written -- `stability
// --scene` writes its own --, hidden modes, Assumption 1(a)): asking for one is refused by name (exit 2).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/multidof/scene_analysis.hpp"
#include "hapstab/scene/scene.hpp"

namespace hapstab::cli {

/// "" when the scene's model can be written in a multidof certificate (either kind), else why not
/// (checked before the analysis runs): an environment given by `ss`, `qv_block_diagonal = true`,
/// a device whose OSP level is a certified bound rather than exact or declared. A compact
/// environment (diagonal / off_diagonal, list parameters) is written out (scene::environment_expressions).
std::string multidof_certificate_premise(const scene::Scene& sc);

/// The operator-passivity certificate of `a` (above) when (16) is proven feasible and Assumption 1(b)
/// fails for a tf operator the checkers verify it for; nullopt otherwise (the (16) kinds then).
std::optional<nlohmann::json> operator_passivity_certificate(const std::string& scene_path, const std::vector<std::string>& sets,
                                                             const multidof::SceneAnalysis& a);

/// The certificate of `a`'s verdict on (16): feasible (its exact point) or infeasible by a
/// frequency-domain witness, verified by check/ before it is returned. InputError (exit 2, no file)
/// for any other verdict, naming it, or an E-hat beyond the checkers' size (order 160).
nlohmann::json multidof_certificate(const scene::Scene& sc, const multidof::SceneAnalysis& a);

/// `multidof design --certificate FILE` (kind multidof-coupling, check/multidof_coupling_check.hpp):
/// the designed V meets Theorem 4 through Theorem 5 -- (16) at an exact point (P_E, X, Q_E, Q_V) on
/// E-hat's realisation, and Lemma 1 for V-hat (17) at that X and Q_V with an exact storage P_V. The
/// evidence is the block-wise design's own (its point, the blocks' storages) where V was designed on
/// the whole block by block; on the split, the split's block points and one storage
/// per DOF (kind multidof-coupling-symmetric); otherwise Theorem 4's program on the whole for that V
/// (check_theorem4). InputError (exit 2, no file) when no V was verified exactly, when that program
/// does not certify V (its size limit, or no exact point), or beyond the checkers' order 160.
nlohmann::json design_certificate(const scene::Scene& sc, const multidof::SceneDesign& d, const lmi::Options& opt);

}  // namespace hapstab::cli
