// The files a study writes: study.csv (one row per run), study.md (the same table,
// the reference, observed orders and the advice lines) and study.png.
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include "study/study.hpp"

namespace moorsph::app::study {
namespace {

std::string num(double x, const char* fmt = "%.6g") {
  if (std::isnan(x)) return "n/a";
  char text[64];
  std::snprintf(text, sizeof text, fmt, x);
  return text;
}

std::string csvNum(double x) { return std::isnan(x) ? "" : num(x, "%.10g"); }

// Two log-log panels: relative error against wall time and against fluid particles,
// one line per variant, each point labelled with its dx.
const char* const kStudyPlotScript = R"PY(
import csv, math, sys
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FormatStrFormatter, FuncFormatter, NullFormatter
except ImportError as error:
    print(f"study plot needs matplotlib in {sys.executable}: {error}")
    sys.exit(77)
out, title = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(f"{out}/study.csv")))
variants = []
for r in rows:
    if r["variant"] not in variants:
        variants.append(r["variant"])
fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
plotted = 0
for v in variants:
    pts = [r for r in rows if r["variant"] == v and r["relative_error"] not in ("", "0")]
    pts = [r for r in pts if float(r["relative_error"]) > 0]
    if not pts:
        continue
    err = [100 * float(r["relative_error"]) for r in pts]
    for ax, key in zip(axes, ("wall_s", "fluid_particles")):
        x = [float(r[key]) for r in pts]
        ax.loglog(x, err, "o-", label=v or "runs")
        for xi, ei, r in zip(x, err, pts):
            ax.annotate(f"dx={float(r['dx']):g}", (xi, ei), textcoords="offset points", xytext=(4, 4), fontsize=7)
    plotted += 1
axes[0].set_xlabel("wall time [s]")
axes[1].set_xlabel("fluid particles")
for ax in axes:
    ax.set_ylabel("relative error [%]")
    ax.grid(True, which="both", alpha=0.3)
    # Plain numbers; minor ticks labelled only when the axis spans less than a decade, on
    # the x axes only at 2 and 5 times a power of ten (all eight overlap on long numbers).
    def two_and_five(value, _):
        mantissa = round(value / 10 ** math.floor(math.log10(value))) if value > 0 else 0
        return f"{value:g}" if mantissa in (2, 5) else ""
    for axis, (lo, hi), minor in ((ax.xaxis, ax.get_xlim(), FuncFormatter(two_and_five)),
                                  (ax.yaxis, ax.get_ylim(), FormatStrFormatter("%g"))):
        axis.set_major_formatter(FormatStrFormatter("%g"))
        axis.set_minor_formatter(minor if hi < 10 * lo else NullFormatter())
if len(variants) > 1:
    axes[0].legend(fontsize=7)
fig.suptitle(title, fontsize=9)
fig.tight_layout()
fig.savefig(f"{out}/study.png", dpi=110)
print(f"wrote {out}/study.png ({plotted} series)")
)PY";

void writeCsv(std::ostream& f, const std::vector<StudyRow>& rows) {
  f << "variant,dx,fluid_particles,boundary_particles,steps,wall_s,value,reference,error,relative_error,observed_order\n";
  for (const auto& r : rows)
    f << '"' << r.variant << "\"," << csvNum(r.dx) << ',' << r.fluid_particles << ',' << r.boundary_particles << ','
      << r.steps << ',' << csvNum(r.wall_seconds) << ',' << csvNum(r.value) << ',' << csvNum(r.reference) << ','
      << csvNum(r.error) << ',' << csvNum(r.relative_error) << ',' << csvNum(r.order) << '\n';
}

void writeMarkdown(std::ostream& f, const StudyOptions& o, const std::vector<StudyRow>& rows,
                   const std::vector<VariantSummary>& summaries, double simulated) {
  f << "# Study: " << o.scene << ", metric " << o.metric << (o.series.empty() ? "" : " of " + o.series) << "\n\n";
  f << "Simulated time per run: " << num(simulated, "%g") << " s; threads: "
    << (o.threads > 0 ? std::to_string(o.threads) : std::string("default")) << ".";
  if (!std::isnan(o.params.time)) f << " Metric at t = " << num(o.params.time, "%g") << " s.";
  if (std::isfinite(o.params.window.from) || std::isfinite(o.params.window.to))
    f << " Window [" << num(o.params.window.from, "%g") << ", " << num(o.params.window.to, "%g") << "] s.";
  f << "\nWall times are this machine's, as measured (inflated when the machine is shared).\n\n";
  for (const auto& s : summaries)
    f << "- reference" << (s.variant.empty() ? "" : " (" + s.variant + ")") << ": " << num(s.reference) << " — "
      << s.reference_source << "\n";
  f << "\n| variant | dx [m] | fluid particles | steps | wall [s] | value | error | rel. error | observed order |\n"
    << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& r : rows)
    f << "| " << (r.variant.empty() ? "-" : r.variant) << " | " << num(r.dx, "%g") << " | " << r.fluid_particles << " | "
      << r.steps << " | " << num(r.wall_seconds, "%.3g") << " | " << num(r.value) << " | " << num(r.error, "%.3g")
      << " | " << (std::isnan(r.relative_error) ? "n/a" : num(100.0 * r.relative_error, "%.3g") + "%") << " | "
      << num(r.order, "%.2f") << " |\n";
  f << "\nObserved order: from each run and the next coarser one, p = ln(e1/e2) / ln(dx1/dx2).";
  bool richardson = false, finest = false;
  for (const auto& s : summaries) {
    richardson = richardson || s.richardson_order.has_value();
    finest = finest || s.finest_is_reference;
  }
  if (richardson)
    f << " Against the Richardson extrapolate, the orders of the two finest pairs restate the extrapolation's own "
         "order (equal for a constant dx ratio); only coarser pairs check it independently.";
  if (finest)
    f << " Against the finest run, that run's own error is undefined and the next runs' errors are only known to "
         "within the reference's uncertainty.";
  f << "\n\n";
  f << "## Advice\n\n";
  for (const auto& line : adviceLines(rows, o.metric, simulated)) f << "- " << line << "\n";
  f << "\n![error against cost](study.png)\n";
}

}  // namespace

int plotStudy(const std::string& out, const std::string& title) {
  const char* python = std::getenv("MOORSPH_PYTHON") ? std::getenv("MOORSPH_PYTHON") : "/usr/bin/python3";
  const std::string script = out + "/.study_plot_" + std::to_string(getpid()) + ".py";
  std::ofstream(script) << kStudyPlotScript;
  std::string quoted_title;
  for (char c : title) quoted_title += c == '\'' ? std::string("'\\''") : std::string(1, c);
  const std::string command = std::string(python) + " '" + script + "' '" + out + "' '" + quoted_title + "'";
  const int status = std::system(command.c_str());
  std::filesystem::remove(script);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool writeStudyReport(const std::string& out, const StudyOptions& o, const std::vector<StudyRow>& rows,
                      const std::vector<VariantSummary>& summaries, double simulated) {
  {
    std::ofstream csv(out + "/study.csv");
    writeCsv(csv, rows);
    std::ofstream md(out + "/study.md");
    writeMarkdown(md, o, rows, summaries, simulated);
    if (!csv || !md) {
      std::fprintf(stderr, "error: cannot write %s/study.csv or study.md\n", out.c_str());
      return false;
    }
  }
  const int plot = plotStudy(out, std::filesystem::path(o.scene).filename().string() + ": " + o.metric);
  if (plot == 77 || plot == 127)
    std::fprintf(stderr, "warning: no study.png: plotting needs /usr/bin/python3 with matplotlib\n");
  else if (plot != 0)
    std::fprintf(stderr, "warning: the study plot script failed (exit %d); study.md and study.csv are written\n", plot);
  return true;
}

}  // namespace moorsph::app::study
