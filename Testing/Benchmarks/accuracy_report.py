#!/usr/bin/python3
"""Tables and plots of the speed-against-error report.

Reads the JSON lines run_accuracy_report.sh collected (one per reference and per solve)
and writes, in OUT_DIR: report.json (every run), report.md (a table per scene) and
<scene>.png (error against time, log-log: one panel per component, one curve per
method). Errors are relative to the reference's mean of that component; the
reference's own standard error is shown, and marked where it is not at least five
times below the error it measures.

With DOC (docs/validation.md), the same tables and plots are also written there, as
the project's validation page, its plots linked in OUT_DIR.

Peer runs in OUT_DIR/rsun.jsonl (run_rsun_accuracy.sh: GRASS r.sun on the same scenes)
join the tables and plots as single points, with a table of where TerraLux's knob lies
against them.

Usage: /usr/bin/python3 accuracy_report.py RUNS.jsonl OUT_DIR [DOC]
       /usr/bin/python3 accuracy_report.py OUT_DIR/report.json OUT_DIR [DOC]  (again from a report)
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COMPONENTS = ("sun", "sky", "reflected", "global")
BAND_POINTS = 30  # fewer points in a band of reflected light: its bias is not shown
METHODS = {"points": "patches, at points", "points-previous": "patches, at points, previous release",
           "rays": "patches, at points, sky by rays", "averaged": "patches, averaged",
           "triangles": "triangles, at points", "rsun": "GRASS r.sun",
           "rsun-horizons": "GRASS r.sun with r.horizon"}
# Peer tools' runs (run_rsun_accuracy.sh writes them to OUT_DIR/rsun.jsonl): one point each.
PEERS = ("rsun", "rsun-horizons")
# One colour per method in every panel and plot.
COLOURS = dict(zip(METHODS, ("tab:blue", "tab:orange", "tab:purple", "tab:green", "tab:brown", "tab:red",
                             "tab:pink")))


# The defaults (ErrorTolerance, TargetError) and the knob's coarse end (the command's --fast).
DEFAULT_TOLERANCE, DEFAULT_TARGET, COARSE_TARGET = 1e-2, 0.008, 0.04


def percent(x):
    return "%.2f" % (100.0 * x)


def at_points(run):
    return run["method"] != "averaged" and "target_error" in run


def knob(run):
    """The setting a run was swept over: TargetError at points, ErrorTolerance averaged."""
    return run["target_error"] if at_points(run) else run["tolerance"]


def on_knob(run):
    """A run of the knob's sweep: at points, the default ErrorTolerance."""
    return run["method"] == "points" and run["tolerance"] == DEFAULT_TOLERANCE and "target_error" in run


def at_defaults(run, target=DEFAULT_TARGET):
    return on_knob(run) and run["target_error"] == target


def drawn_again(run):
    """A solve at the defaults drawn again with another RandomSeed (the seeds' spread)."""
    return run.get("random_seed", 0) != 0


def over_seeds(values):
    """Mean and standard deviation (n - 1) of a value over the seeds' solves."""
    mean = sum(values) / len(values)
    spread = (sum((v - mean) ** 2 for v in values) / (len(values) - 1)) ** 0.5 if len(values) > 1 else 0.0
    return mean, spread


def load(path):
    references, solves = {}, []
    if path.endswith(".json"):  # a report written before: its runs again
        with open(path) as f:
            report = json.load(f)
        return report["references"], report["solves"]
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line.startswith("{"):
                continue
            run = json.loads(line)
            if "reference_seconds" in run:
                references[run["scene"]] = run
            else:
                solves.append(run)
    return references, solves


def table(scene, reference, runs):
    lines = ["### %s" % scene, ""]
    if reference:
        lines.append("Reference: %d points, %d directions each, %.1f s." % (
            reference["points"], reference["samples"], reference["reference_seconds"]))
        lines.append("")
    lines.append("| method | tolerance | target error | time s | x floor | peak MiB | elements | links | rays | "
                 "global RMS % | p95 % | max % | bias % | sky RMS % | reflected bias % | "
                 "shadow disagree % | reference SE % | estimate holds % | estimate median % |")
    lines.append("|" + "---|" * 19)
    for run in runs:
        g, sky, refl = run["global"], run["sky"], run["reflected"]
        floor = run["floor_seconds"]
        times = "%.0f" % (run["seconds"] / floor) if floor > 0 else "-"
        noisy = g["reference_error"] * 5 > g["rms"] and g["rms"] > 0
        estimate = run.get("estimate")
        peer = run["method"] in PEERS
        lines.append("| %s | %s | %s | %.3f | %s | %.0f | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s%s | %s | %s |" % (
            METHODS.get(run["method"], run["method"]), "-" if peer else "%g" % run["tolerance"],
            "%g" % run["target_error"] if at_points(run) else "-", run["seconds"], times, run["peak_mib"],
            *(("-",) * 3 if peer else (run["elements"], run["links"], run["rays"])), percent(g["rms"]), percent(g["p95"]), percent(g["max"]),
            percent(g["bias"]), percent(sky["rms"]), percent(refl["bias"]) if refl["mean"] > 0 else "-",
            percent(run["shadow_disagreement"]), percent(g["reference_error"]), " (noisy)" if noisy else "",
            percent(estimate["coverage"]) if estimate else "-", percent(estimate["median"]) if estimate else "-"))
    lines.append("")
    lines += phases(runs)
    return lines


def band_shown(band):
    """Whether a band of reflected light holds enough points, and light, to show its bias."""
    return band["posts"] >= BAND_POINTS and band["error"]["mean"] > 0


def reflected_bands(run):
    """The reflected bias in each band of reflected light (as the reference's estimate for
    bands tells), from below 1 W/m^2 up, as 'a / b / c / d' (- where a band is not shown)."""
    bands = run.get("reflected_bands")
    if not bands:
        return "-"
    return " / ".join(percent(b["error"]["bias"]) if band_shown(b) else "-" for b in bands)


def band_table(solves, seeded=()):
    """Reflected light at the defaults by band of what the points receive of it: each band's
    bias, relative and in W/m^2, and its points; with the defaults drawn again on other
    seeds, each band's bias over them all (mean and spread), and the overall bias's."""
    runs = sorted((r for r in solves if at_defaults(r) and r.get("reflected_bands")), key=lambda r: r["scene"])
    if not runs:
        return []
    draws = {}
    for run in runs + [r for r in seeded if at_defaults(r) and r.get("reflected_bands")]:
        draws.setdefault(run["scene"], []).append(run)
    seeds = max(len(d) for d in draws.values())
    lines = ["### Reflected light by band", "",
             "At the defaults, the points grouped by what they receive of reflected light, as a second "
             "estimate of the reference's tells (an eighth of its directions, on seeds of their own: chosen by "
             "either value compared, a band would hold the points whose noise pushed them in). Each cell: "
             "the band's bias over its reference mean, the same in W/m^2, and its points (- where fewer "
             "than %d)." % BAND_POINTS, "",
             "| scene | below 1 W/m^2 | 1-10 W/m^2 | 10-50 W/m^2 | from 50 W/m^2 |", "|---|---|---|---|---|"]
    for run in runs:
        cells = []
        for band in run["reflected_bands"]:
            error = band["error"]
            cells.append("%s %% = %.3f W/m^2 (%d)" % (percent(error["bias"]), error["bias"] * error["mean"], band["posts"])
                         if band_shown(band) else "-")
        lines.append("| %s | %s |" % (run["scene"], " | ".join(cells)))
    if seeds < 2:
        return lines + [""]
    lines += ["", "The same solve drawn on %d seeds (RandomSeed 0 to %d; the command's `--seed`): each band's "
              "bias, their mean and standard deviation over the seeds (%%). A band whose mean lies within its "
              "spread of 0 is biased by the solve's sampling noise alone (IrradianceError bounds it per point); "
              "a mean far beyond its spread is a bias of the method." % (seeds, seeds - 1), "",
              "| scene | reflected overall | below 1 W/m^2 | 1-10 W/m^2 | 10-50 W/m^2 | from 50 W/m^2 |",
              "|---|---|---|---|---|---|"]
    for scene in sorted(draws):
        runs_of = draws[scene]
        cells = ["%.2f ± %.2f" % tuple(100.0 * x for x in over_seeds([r["reflected"]["bias"] for r in runs_of]))
                 if runs_of[0]["reflected"]["mean"] > 0 else "-"]
        for k, band in enumerate(runs_of[0]["reflected_bands"]):
            cells.append("%.2f ± %.2f" % tuple(
                100.0 * x for x in over_seeds([r["reflected_bands"][k]["error"]["bias"] for r in runs_of]))
                if band_shown(band) else "-")
        lines.append("| %s | %s |" % (scene, " | ".join(cells)))
    return lines + [""]


def summary(solves, seeded=()):
    """Every scene at the defaults (at points, ErrorTolerance 1e-2, TargetError 0.008) and at
    the knob's coarse end: the accuracy targets and the error estimate's."""
    lines = ["## At the defaults", "",
             "At points, ErrorTolerance %g, TargetError %g; the coarse end is TargetError %g (the command's "
             "`--fast`). Targets: global RMS at most 0.5 %% (2 %% at the coarse end), p95 at most 1 %%, reflected "
             "light within 3 %% of the reference's mean, overall and in each band of what the reference's points "
             "receive of it (below 1, 1-10, 10-50 and from 50 W/m^2; a band of fewer than %d points is not shown); "
             "IrradianceError holding the difference from the "
             "reference (widened by twice the reference's standard error, in quadrature) at 90 %% of points "
             "or more, its median at most 2 %% of the mean global." % (DEFAULT_TOLERANCE, DEFAULT_TARGET, COARSE_TARGET,
                                                           BAND_POINTS),
             "",
             "| scene | time s | global RMS % | p95 % | reflected bias % | by band % | estimate holds % | "
             "estimate median % | coarse end: time s | global RMS % |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    coarse = {r["scene"]: r for r in solves if at_defaults(r, COARSE_TARGET)}
    for run in sorted((r for r in solves if at_defaults(r)), key=lambda r: r["scene"]):
        g, refl, estimate = run["global"], run["reflected"], run.get("estimate")
        fast = coarse.get(run["scene"])
        lines.append("| %s | %.2f | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            run["scene"], run["seconds"], percent(g["rms"]), percent(g["p95"]),
            percent(refl["bias"]) if refl["mean"] > 0 else "-", reflected_bands(run),
            percent(estimate["coverage"]) if estimate else "-", percent(estimate["median"]) if estimate else "-",
            "%.2f" % fast["seconds"] if fast else "-", percent(fast["global"]["rms"]) if fast else "-"))
    return lines + [""] + band_table(solves, seeded)


def against_peers(solves, peers):
    """Each scene r.sun ran on: its points beside TerraLux's knob (at points, the default
    ErrorTolerance). TerraLux lies below and to the left where one of its settings is at
    most as slow and at most as far off as r.sun's run."""
    if not peers:
        return []
    lines = ["## Against GRASS r.sun", "",
             "r.sun's instant on the same DEM, its sun, beam normal and diffuse horizontal irradiance and "
             "albedo matched to the scene's (`Testing/Benchmarks/run_rsun_accuracy.sh`), against the same "
             "reference; times are r.horizon and r.sun alone (nprocs=2), as TerraLux's are its solve's. "
             "Below and left: a TerraLux setting at most as slow and at most as far off.", "",
             "| scene | r.sun run | time s | global RMS % | sky bias % | reflected bias % | "
             "TerraLux defaults: time s | global RMS % | coarsest: time s | global RMS % | below and left |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for peer in sorted(peers, key=lambda r: (r["scene"], r["method"])):
        knob_runs = [r for r in solves if r["scene"] == peer["scene"] and on_knob(r)]
        if not knob_runs:
            continue
        default = next((r for r in knob_runs if r["target_error"] == DEFAULT_TARGET), None)
        coarsest = max(knob_runs, key=lambda r: r["target_error"])
        dominated = any(r["seconds"] <= peer["seconds"] and r["global"]["rms"] <= peer["global"]["rms"]
                        for r in knob_runs)
        lines.append("| %s | %s | %.2f | %s | %s | %s | %s | %s | %.2f | %s | %s |" % (
            peer["scene"], METHODS[peer["method"]], peer["seconds"], percent(peer["global"]["rms"]),
            percent(peer["sky"]["bias"]), percent(peer["reflected"]["bias"]),
            "%.2f" % default["seconds"] if default else "-", percent(default["global"]["rms"]) if default else "-",
            coarsest["seconds"], percent(coarsest["global"]["rms"]), "yes" if dominated else "no"))
    return lines + [""]


def load_peers(out_dir):
    path = os.path.join(out_dir, "rsun.jsonl")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip().startswith("{")]


def phases(runs):
    """Share of time and rays by phase, for each output mode at its defaults."""
    rows = [r for r in runs if r["tolerance"] == DEFAULT_TOLERANCE and "phase_rays" in r and
            (not at_points(r) or r["target_error"] == DEFAULT_TARGET)]
    if not rows:
        return []
    lines = ["Time and rays by phase at the defaults (visibility build and the posts' horizons, refinement, "
             "gather and push-pull, point values):", "",
             "| method | time: build / refine / gather, push-pull / points | rays: refine / gather, push-pull / points |",
             "|---|---|---|"]
    for run in rows:
        t, n = run["phase_seconds"], run["phase_rays"]
        build = t["visibility"] + t.get("horizons", 0.0)
        total_t = max(1e-12, build + t["refine"] + t["gather"] + t["push_pull"] + t["points"])
        total_n = max(1, n["refine"] + n["gather_push_pull"] + n["points"])
        lines.append("| %s | %.0f / %.0f / %.0f / %.0f %% | %.0f / %.0f / %.0f %% |" % (
            METHODS.get(run["method"], run["method"]), 100 * build / total_t, 100 * t["refine"] / total_t,
            100 * (t["gather"] + t["push_pull"]) / total_t, 100 * t["points"] / total_t,
            100 * n["refine"] / total_n, 100 * n["gather_push_pull"] / total_n, 100 * n["points"] / total_n))
    lines.append("")
    return lines


def plot(scene, runs, out_dir):
    figure, axes = plt.subplots(1, 4, figsize=(16, 4), sharex=True)
    for axis, component in zip(axes, COMPONENTS):
        for method, label in METHODS.items():
            points = [(r["seconds"], r[component]["rms"]) for r in runs
                      if r["method"] == method and r[component]["mean"] > 0 and r[component]["rms"] > 0]
            if points:
                points.sort()
                axis.loglog([p[0] for p in points], [100 * p[1] for p in points],
                            "*" if method in PEERS else "o-", markersize=12 if method in PEERS else 6,
                            color=COLOURS[method], label=label)
        errors = [r[component]["reference_error"] for r in runs if r[component]["mean"] > 0]
        if errors and max(errors) > 0:
            axis.axhline(100 * max(errors), color="grey", linestyle=":", label="reference SE")
        axis.set_title("%s: %s" % (scene, component))
        axis.set_xlabel("wall time (s)")
        axis.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("relative RMS error (%)")
    # Below the panels, where it hides no point; each label once.
    labels = {}
    for axis in axes:
        for handle, label in zip(*axis.get_legend_handles_labels()):
            labels.setdefault(label, handle)
    figure.legend(labels.values(), labels.keys(), loc="lower center", ncol=len(labels), fontsize=8)
    figure.tight_layout(rect=(0, 0.08, 1, 1))
    path = os.path.join(out_dir, "%s.png" % scene)
    figure.savefig(path, dpi=90)
    plt.close(figure)
    return path


def main():
    references, solves = load(sys.argv[1])
    seeded = [r for r in solves if drawn_again(r)]
    out_dir = sys.argv[2]
    peers = load_peers(out_dir)
    if os.path.abspath(sys.argv[1]) != os.path.abspath(os.path.join(out_dir, "report.json")):
        with open(os.path.join(out_dir, "report.json"), "w") as f:
            json.dump({"references": references, "solves": solves}, f, indent=1)
    solves = [r for r in solves if not drawn_again(r)]
    lines = ["# Speed against error", "",
             "Errors per component over the reference's mean (RMS, 95th percentile, maximum, bias); "
             "global over the points where TerraLux and the reference agree on shadow. "
             "x floor: the solve's time over one Embree occlusion ray per point toward the sun.", ""]
    doc = sys.argv[3] if len(sys.argv) > 3 else None
    images = os.path.relpath(out_dir, os.path.dirname(os.path.abspath(doc))) if doc else None
    doc_lines = ["# Validation", "",
                 "TerraLux against an independent reference: a Monte Carlo path tracer on its own Embree "
                 "scene (`Testing/Reference`, validated against closed forms by its own tests), on the scenes "
                 "of `Testing/Benchmarks/accuracy_scenes.cxx`. Generated by the accuracy report "
                 "(`bash Testing/Benchmarks/run_accuracy_report.sh build docs/validation`, with "
                 "`TERRALUX_REPORT_DOC=docs/validation.md`); do not edit by hand.", ""] + lines[2:]
    sections = summary(solves, seeded) + against_peers(solves, peers)
    lines += sections
    doc_lines += sections
    for scene in sorted({r["scene"] for r in solves}):
        runs = [r for r in solves + peers if r["scene"] == scene]
        runs.sort(key=lambda r: (list(METHODS).index(r["method"]), -knob(r)))
        rows = table(scene, references.get(scene), runs)
        lines += rows + ["![%s](%s.png)" % (scene, scene), ""]
        if doc:
            doc_lines += rows + ["![%s](%s/%s.png)" % (scene, images, scene), ""]
        plot(scene, runs, out_dir)
    with open(os.path.join(out_dir, "report.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s" % os.path.join(out_dir, "report.md"))
    if doc:
        with open(doc, "w") as f:
            f.write("\n".join(doc_lines) + "\n")
        print("wrote %s" % doc)


if __name__ == "__main__":
    main()
