#include "cli/reproduce.hpp"

#include <algorithm>

#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"

namespace hapstab::cli {

namespace fs = std::filesystem;
using proofs::ClaimResult;

const char* paper_title(const std::string& p) {
  if (p == "000")
    return "Bianchini, Orlandesi, Prattichizzo: An LMI framework for analysis and design of multi-dimensional "
           "haptic systems";
  if (p == "001") return "Roberts, Moore, Colgate: A new expression for the passivity bound for a class of sampled-data systems";
  if (p == "002") return "Tsai, Colgate: Stability of discrete time systems with unilateral nonlinearities";
  if (p == "ext")
    return "Beyond the papers: the stability boundary of the haptic loop, quantization and Coulomb friction, "
           "passivity control in time, Z-width";
  if (p == "python") return "From Python: the examples in examples/python, drawn with matplotlib";
  return "The toolbox's own charts";
}

namespace {
/// "Paper 001: ..." for a paper, the title alone for the toolbox's and Python's sections.
std::string section_title(const std::string& p) {
  return (p == "toolbox" || p == "python" || p == "ext" ? "" : "Paper " + p + ": ") + paper_title(p);
}
}  // namespace

namespace {
const char* const claim_table_columns[] = {"claim", "equation", "statement", "method", "verdict"};

// The cells of a markdown table line "| a | b \\| c |": split at each '|' that no backslash
// escapes, trimmed (an escaped character is kept with its backslash, as md::cell wrote it).
std::vector<std::string> split_row(const std::string& line) {
  std::vector<std::string> cells;
  std::string cur;
  bool started = false;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size()) {
      cur += line.substr(i, 2);
      ++i;
    } else if (line[i] == '|') {
      if (started) cells.push_back(cur);
      started = true;
      cur.clear();
    } else {
      cur += line[i];
    }
  }
  for (auto& c : cells) {
    const size_t a = c.find_first_not_of(' '), b = c.find_last_not_of(' ');
    c = a == std::string::npos ? "" : c.substr(a, b - a + 1);
  }
  return cells;
}
}  // namespace

std::vector<std::string> claim_table_cells(const ClaimResult& c) {
  using report::markdown::cell;
  return {report::markdown::code(c.id), cell(c.equation), cell(c.statement), to_string(c.status),
          c.holds ? "holds" : "FAILS"};
}

std::string claim_table_row(const ClaimResult& c) {
  std::string row = "|";
  for (const auto& x : claim_table_cells(c)) row += " " + x + " |";
  return row;
}

std::string claim_table_header() { return "| claim | equation | statement | method | verdict |\n|---|---|---|---|---|\n"; }

std::vector<std::string> compare_claim_table(const std::vector<ClaimResult>& claims, const std::string& text,
                                             const std::string& papers_run) {
  std::map<std::string, std::vector<std::string>> rows;  // id -> cells
  std::vector<std::string> msgs, order;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    auto cells = split_row(line);
    if (cells.empty() || cells[0].size() < 2) continue;
    const std::string id = cells[0].substr(1, cells[0].size() - 2);
    if (rows.count(id)) msgs.push_back("claim `" + id + "`: more than one row in the table");
    rows[id] = std::move(cells);
    order.push_back(id);
  }
  std::set<std::string> seen;
  for (const auto& c : claims) {
    seen.insert(c.id);
    const auto it = rows.find(c.id);
    if (it == rows.end()) {
      msgs.push_back("claim `" + c.id + "` has no row in the table");
      continue;
    }
    const auto want = claim_table_cells(c);
    const auto& got = it->second;
    if (got.size() != want.size()) {
      msgs.push_back("claim `" + c.id + "`: its row has " + std::to_string(got.size()) + " columns, not " +
                     std::to_string(want.size()));
      continue;
    }
    for (size_t k = 1; k < want.size(); ++k)
      if (got[k] != want[k])
        msgs.push_back("claim `" + c.id + "`: column " + claim_table_columns[k] + ": the table says '" + got[k] +
                       "', the claim '" + want[k] + "'");
  }
  for (const auto& id : order)
    if (!seen.count(id) && (papers_run.empty() || id.rfind(papers_run + ".", 0) == 0))
      msgs.push_back("claim `" + id + "`: a row in the table, but no such claim");
  return msgs;
}

int claim_table_differences(const std::vector<ClaimResult>& claims, const std::string& table, const std::string& papers_run,
                            const std::string& who) {
  std::ifstream in(table);
  if (!in) throw InputError("--table: cannot read '" + table + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  const auto msgs = compare_claim_table(claims, ss.str(), papers_run);
  for (const auto& m : msgs) std::cerr << "hapstab " << who << ": " << table << ": " << m << "\n";
  return static_cast<int>(msgs.size());
}

std::vector<ClaimResult> run_proofs(const std::string& only, bool quiet, double& seconds) {
  std::vector<ClaimResult> all;
  auto t0 = std::chrono::steady_clock::now();
  const auto& reg = proofs::registry();
  if (reg.empty())
    throw InputError("this program was built without the proofs (the Python module, or a build configured with "
                     "-DHAPSTAB_PROOFS=OFF such as scripts/configure-asan's): run them with the command of a Release "
                     "build, build/hapstab");
  size_t i = 0, total = 0;
  for (const auto& p : reg) total += only.empty() || only == p.paper;
  for (const auto& p : reg) {
    if (!only.empty() && only != p.paper) continue;
    ++i;
    proofs::Checker check(p.paper);
    auto s0 = std::chrono::steady_clock::now();
    try {
      p.run(check);
    } catch (const std::exception& e) {
      check.claim(std::string(p.paper) + "." + p.id + ".completes", "-",
                  std::string("proof ran to the end: ") + p.title, Status::exact, false,
                  std::string("threw: ") + e.what());
    }
    for (const auto& id : check.unclaimed())  // a certificate asked for a claim the proof never made
      check.claim(std::string(p.paper) + "." + p.id + ".certificates", "-",
                  std::string("every certificate the proof asks for belongs to one of its claims: ") + p.title, Status::exact,
                  false, "certify() or no_certificate() named '" + id + "', which no claim of the proof has");
    double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
    if (!quiet) {
      std::cout << "[proof " << i << "/" << total << "] " << p.paper << " " << p.id << ": "
                << check.results().size() << " claims, " << dt << " s\n";
      for (const auto& c : check.results())
        std::cout << (c.holds ? "  holds  " : "  FAILS  ") << c.id << "  " << c.equation << "  ["
                  << to_string(c.status) << "]  " << c.evidence << "\n";
    }
    all.insert(all.end(), check.results().begin(), check.results().end());
  }
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return all;
}

namespace {

const char* const kPapers[] = {"001", "002", "000", "ext", "toolbox", "python"};

using report::markdown::cell;
using report::markdown::code;
using report::html::attribute;
using report::html::url_component;
std::string html(const std::string& s) { return report::html::text(s); }

std::ofstream open_out(const fs::path& p) {
  fs::create_directories(p.parent_path());
  std::ofstream out(p);
  if (!out) throw InputError("--out: cannot write " + p.string());
  return out;
}

size_t count_failures(const ReportInput& in) {
  size_t n = 0;
  for (const auto& c : in.claims) n += !c.holds;
  for (const auto& f : in.figures) n += !f.ok && !f.skipped;
  for (const auto& r : in.scenes) n += !r.ok;
  return n + in.certificate_summary.failed;
}

template <class T>
bool any_of_paper(const std::vector<T>& v, const std::string& paper) {
  for (const auto& x : v)
    if (x.paper == paper) return true;
  return false;
}

std::string summary_line(const ReportInput& in) {
  size_t cf = 0, ff = 0, fs_ = 0, sf = 0;
  for (const auto& c : in.claims) cf += !c.holds;
  for (const auto& f : in.figures) ff += !f.ok && !f.skipped, fs_ += f.skipped;
  for (const auto& r : in.scenes) sf += !r.ok;
  std::ostringstream o;
  o << in.claims.size() << " claims checked (" << in.claims.size() - cf << " hold, " << cf << " fail); "
    << in.scenes.size() << " scene runs (" << in.scenes.size() - sf << " as expected, " << sf << " not); "
    << in.figures.size() << " figures (" << in.figures.size() - ff - fs_ << " drawn, " << ff << " failed, " << fs_
    << " not reproduced on this build); " << in.seconds << " s.";
  return o.str();
}

// The certificate cell of a scene run: a simulation has none, except the certificate of its one-DOF
// linear loop's stability where it has one; `multidof analyze` and `design` link their certificates
// (produce_scene_certificates), or say why their verdict has none.
std::string scene_certificate(const SceneRun& r, const std::vector<CertificateEntry>& entries, bool as_html) {
  auto text = [&](const std::string& t) { return as_html ? html(t) : cell(t); };
  const bool certified_loop = std::any_of(entries.begin(), entries.end(), [&](const CertificateEntry& e) { return e.claim == scene_claim_id(r); });
  if (r.command == "simulate" && certified_loop)
    return text("the simulated trend is numeric; the loop's stability, which it shows: ") +
           certificate_cell(ClaimResult{scene_claim_id(r), r.paper, "", r.claim, Status::certified, r.ok, ""}, entries, as_html);
  if (r.command == "simulate") return text("numeric (a simulation): no certificate");
  if (r.command != "multidof analyze" && r.command != "multidof design") return text("no certificate kind yet (issue 47)");
  ClaimResult as_claim{scene_claim_id(r), r.paper, "", r.claim, Status::exact, r.ok, ""};
  as_claim.no_certificate = r.no_certificate;
  return certificate_cell(as_claim, entries, as_html);
}

// The report's certificate paragraph: the counts, the times, the failures.
std::string certificate_paragraph(const ReportInput& in, bool as_html) {
  const CertificateSummary& s = in.certificate_summary;
  std::ostringstream o;
  const std::string counts = certificate_counts(s, !as_html);
  o << (as_html ? "<b>Certificates</b> (issue 47, docs/certificates.md): " + html(counts) : "**Certificates** (issue 47, docs/certificates.md): " + counts)
    << ". Production " << s.produce_seconds << " s (the commands, in this process), `hapstab check` " << s.check_seconds
    << " s, the independent checker " << s.independent_seconds << " s (the checks themselves); "
    << s.wall_seconds << " s for the checks on two workers. Sizes and times of each: "
    << (as_html ? "<a href=\"certificates/index.json\">certificates/index.json</a>" : "[certificates/index.json](certificates/index.json)")
    << ".";
  std::string text = o.str();
  if (as_html) {  // the backquotes of the markdown text as <code>
    const std::string tick = "`hapstab check`";
    for (size_t at; (at = text.find(tick)) != std::string::npos;) text.replace(at, tick.size(), "<code>hapstab check</code>");
  }
  for (const auto& f : s.failures) text += as_html ? "<br>\nFAILS: " + html(f) : "\n- **FAILS**: " + cell(f);
  return text;
}

const char* const kStatusLegend =
    "Status: **exact** = proven in rational arithmetic; **certified** = proven by an enclosure; "
    "**numeric** = floating-point evidence with the stated error.";

}  // namespace

std::string certificate_cell(const ClaimResult& c, const std::vector<CertificateEntry>& entries, bool as_html) {
  auto text = [&](const std::string& t) { return as_html ? html(t) : cell(t); };
  auto link = [&](const std::string& label, const std::string& file) {
    const std::string url = "certificates/" + url_component(file.substr(file.find('/') + 1));
    return as_html ? "<a href=\"" + attribute(url) + "\">" + html(label) + "</a>" : "[" + cell(label) + "](" + url + ")";
  };
  std::vector<const CertificateEntry*> mine;
  for (const auto& e : entries)
    if (e.claim == c.id) mine.push_back(&e);
  if (mine.empty())
    return text(c.status == Status::numeric ? "numeric: no certificate"
                : c.no_certificate.empty() ? "no certificate kind yet (issue 47)" : c.no_certificate);
  std::set<std::string> kinds;
  size_t hap = 0, ind = 0, limit = 0;
  const CertificateEntry* failed = nullptr;
  for (const auto* e : mine) {
    kinds.insert(e->kind.empty() ? "(none written)" : e->kind);
    hap += e->hapstab.exit == 0, ind += e->independent.exit == 0, limit += e->independent.exit == 3;
    if (!failed && !e->failure.empty()) failed = e;
  }
  std::string kind_list;
  for (const auto& k : kinds) kind_list += (kind_list.empty() ? "" : ", ") + k;
  std::string out;
  if (mine.size() == 1) {
    out = link(mine.front()->file.substr(mine.front()->file.find('/') + 1), mine.front()->file) + " " + text("(" + kind_list + ")");
  } else {
    out = text(std::to_string(mine.size()) + " certificates (" + kind_list + "):");
    for (size_t k = 0; k < mine.size(); ++k) out += " " + link(std::to_string(k + 1), mine[k]->file);
  }
  const size_t n = mine.size();
  std::string verdict;
  if (failed)
    verdict = (as_html ? "<span class=\"fails\">FAILS</span>: " : "**FAILS**: ") + text(failed->file + ": " + failed->failure);
  else if (hap == n && ind == n)
    verdict = text("verified by both checkers");
  else
    verdict = text("verified by hapstab check (" + std::to_string(hap) + " of " + std::to_string(n) + "); the independent checker: " +
                   std::to_string(ind) + " verified" + (limit ? ", " + std::to_string(limit) + " beyond its size limit" : std::string()));
  out += "; " + verdict;
  if (!c.no_certificate.empty()) out += "; " + text(c.no_certificate);
  return out;
}

void write_report_md(const ReportInput& in, const fs::path& dir) {
  auto md = open_out(dir / "report.md");
  md << "# hapstab reproduction report\n\n" << summary_line(in) << "\n\n";
  if (!in.claims.empty()) md << certificate_paragraph(in, false) << "\n\n";
  md << kStatusLegend << "\n";
  for (std::string paper : kPapers) {
    if (!any_of_paper(in.claims, paper) && !any_of_paper(in.figures, paper) && !any_of_paper(in.scenes, paper))
      continue;
    md << "\n## " << section_title(paper) << "\n";
    if (any_of_paper(in.claims, paper)) {
      md << "\n| claim | equation | statement | status | verdict | certificate | evidence |\n|---|---|---|---|---|---|---|\n";
      for (const auto& c : in.claims)
        if (c.paper == paper)
          md << "| " << code(c.id) << " | " << cell(c.equation) << " | " << cell(c.statement) << " | "
             << to_string(c.status) << " | " << (c.holds ? "holds" : "**FAILS**") << " | "
             << certificate_cell(c, in.certificates, false) << " | " << cell(c.evidence) << " |\n";
    }
    if (any_of_paper(in.scenes, paper)) {
      md << "\n### Example scenes\n\n| scene | claim | command | expected | got | verdict | certificate |\n|---|---|---|---|---|---|---|\n";
      for (const auto& r : in.scenes)
        if (r.paper == paper)
          md << "| " << code("examples/" + r.file) << " | " << cell(r.claim) << " | " << code("hapstab " + r.command) << " | "
             << cell(r.expected.empty() ? "runs" : r.expected) << " | " << cell(r.got) << " | "
             << (r.ok ? "as expected" : "**FAILS**: " + cell(r.error)) << " | " << scene_certificate(r, in.certificates, false) << " |\n";
    }
    for (const auto& f : in.figures)
      if (f.paper == paper) {
        md << "\n**" << cell(f.name) << ".** " << cell(f.caption);
        if (f.ok)
          md << "\n\n![" << cell(f.name) << "](figures/" << url_component(f.name + ".png") << ")\n";
        else
          md << " — **not reproduced" << (f.skipped ? "" : " (FAILED)") << "**: " << cell(f.error) << "\n";
      }
  }
}

void write_index_html(const ReportInput& in, const fs::path& dir) {
  auto h = open_out(dir / "index.html");
  const size_t fails = count_failures(in);
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>hapstab reproduction report</title>\n"
       "<style>body{font-family:'DejaVu Sans',sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}"
       "table{border-collapse:collapse;width:100%;font-size:0.85em;margin:1em 0}"
       "td,th{border:1px solid #ccc;padding:4px 6px;vertical-align:top;text-align:left}th{background:#f0f0f0}"
       "code{font-size:0.9em}.holds{color:#116611;font-weight:bold}.fails{color:#b00;font-weight:bold}"
       ".skipped{color:#805b00;font-weight:bold}"
       "figure{margin:1.5em 0}figure img{max-width:100%;border:1px solid #ddd}figcaption{font-size:0.9em;color:#444}"
       ".summary{padding:0.6em 1em;background:"
    << (fails ? "#fdecea" : "#e8f5e9") << ";border-radius:4px}</style></head><body>\n"
    << "<h1>hapstab reproduction report</h1>\n<p class=\"summary\">" << html(summary_line(in)) << "</p>\n"
    << (in.claims.empty() ? std::string() : "<p>" + certificate_paragraph(in, true) + "</p>\n")
    << "<p>Status: <b>exact</b> = proven in rational arithmetic; <b>certified</b> = proven by an enclosure; "
       "<b>numeric</b> = floating-point evidence with the stated error.</p>\n";
  for (std::string paper : kPapers) {
    if (!any_of_paper(in.claims, paper) && !any_of_paper(in.figures, paper) && !any_of_paper(in.scenes, paper))
      continue;
    h << "<h2>" << html(section_title(paper)) << "</h2>\n";
    if (any_of_paper(in.claims, paper)) {
      h << "<table><tr><th>claim</th><th>equation</th><th>statement</th><th>status</th><th>verdict</th>"
           "<th>certificate</th><th>evidence</th></tr>\n";
      for (const auto& c : in.claims)
        if (c.paper == paper)
          h << "<tr><td><code>" << html(c.id) << "</code></td><td>" << html(c.equation) << "</td><td>"
            << html(c.statement) << "</td><td>" << to_string(c.status) << "</td><td class=\""
            << (c.holds ? "holds\">holds" : "fails\">FAILS") << "</td><td>" << certificate_cell(c, in.certificates, true)
            << "</td><td>" << html(c.evidence) << "</td></tr>\n";
      h << "</table>\n";
    }
    if (any_of_paper(in.scenes, paper)) {
      h << "<h3>Example scenes</h3>\n<table><tr><th>scene</th><th>claim</th><th>command</th><th>expected</th>"
           "<th>got</th><th>verdict</th><th>certificate</th></tr>\n";
      for (const auto& r : in.scenes)
        if (r.paper == paper)
          h << "<tr><td><code>examples/" << html(r.file) << "</code></td><td>" << html(r.claim)
            << "</td><td><code>hapstab " << html(r.command) << "</code></td><td>"
            << html(r.expected.empty() ? "runs" : r.expected) << "</td><td>" << html(r.got) << "</td><td class=\""
            << (r.ok ? "holds\">as expected" : "fails\">FAILS: " + html(r.error)) << "</td><td>"
            << scene_certificate(r, in.certificates, true) << "</td></tr>\n";
      h << "</table>\n";
    }
    for (const auto& f : in.figures)
      if (f.paper == paper) {
        const std::string file = url_component(f.name);
        h << "<figure id=\"" << attribute(f.name) << "\">";
        if (f.ok)
          h << "<img src=\"figures/" << file << ".png\" alt=\"" << attribute(f.caption) << "\">";
        else
          h << "<p class=\"" << (f.skipped ? "skipped" : "fails") << "\">not reproduced" << (f.skipped ? "" : " (FAILED)")
            << ": " << html(f.error) << "</p>";
        h << "<figcaption><b>" << html(f.name) << ".</b> " << html(f.caption);
        if (f.ok && f.matplotlib)
          h << " (<a href=\"figures/" << file << ".pdf\">PDF</a>)";
        else if (f.ok)
          h << " (<a href=\"figures/" << file << ".pdf\">PDF</a>, <a href=\"figures/" << file
            << ".svg\">SVG</a>, <a href=\"figures/tex/" << file << ".tex\">LaTeX</a>)";
        h << "</figcaption></figure>\n";
      }
  }
  h << "</body></html>\n";
}

}  // namespace hapstab::cli
