#!/usr/bin/env python3
"""Collects the benchmark runs of tests/bench/run.sh. Only the standard library.

    collect.py record PLATFORM BENCH ARGS EXIT_STATUS STDOUT_FILE TIME_V_FILE   -> one JSON line on stdout
    collect.py report RUNS_JSONL RESULTS_JSON RESULTS_MD MODE              -> the JSON file and the table

A run's results are the JSON objects its benchmark printed (one per line). Peak memory comes from
`/usr/bin/time -v` (maximum resident set size of the whole process: for wasm that is node with the
wasm heap it reserved)."""
import datetime
import json
import os
import platform
import re
import subprocess
import sys

# Flattened metric names containing one of these are context, not figures to compare.
SKIP = ("checksum", "platform", "hardware_threads", "load_average", "seed", "bench", "benchmark")


def parse_time_v(path):
    stats = {}
    with open(path) as f:
        text = f.read()
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    if m:
        stats["max_rss_mib"] = int(m.group(1)) / 1024.0
    m = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([\d:.]+)", text)
    if m:
        seconds = 0.0
        for part in m.group(1).split(":"):
            seconds = seconds * 60 + float(part)
        stats["wall_s"] = seconds
    for key, label in (("user_s", "User time (seconds)"), ("sys_s", "System time (seconds)")):
        m = re.search(re.escape(label) + r": ([\d.]+)", text)
        if m:
            stats[key] = float(m.group(1))
    return stats


def record(platform_name, bench, args, exit_status, stdout_path, time_path):
    # One or more JSON objects, each on one line or pretty-printed over several.
    with open(stdout_path) as f:
        text = f.read()
    results, pos, decoder = [], 0, json.JSONDecoder()
    while True:
        pos = text.find("{", pos)
        if pos < 0:
            break
        try:
            value, pos = decoder.raw_decode(text, pos)
            results.append(value)
        except json.JSONDecodeError:
            pos += 1
    run = {"bench": bench, "args": args, "platform": platform_name, "exit_status": int(exit_status), "results": results}
    run.update(parse_time_v(time_path))
    print(json.dumps(run))


def command_output(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, timeout=60).stdout.strip().splitlines()[0]
    except (OSError, IndexError, subprocess.SubprocessError):
        return "unknown"


def machine():
    info = {"os": platform.platform(), "cores": os.cpu_count()}
    try:
        with open("/proc/cpuinfo") as f:
            models = [l.split(":", 1)[1].strip() for l in f if l.startswith("model name")]
        info["cpu"] = models[0] if models else "unknown"
        with open("/proc/meminfo") as f:
            info["memory_gib"] = round(int(f.readline().split()[1]) / 1024 / 1024, 1)
        with open("/proc/loadavg") as f:
            info["load_average_at_end"] = [float(x) for x in f.read().split()[:3]]
    except OSError:
        pass
    info["native_compiler"] = command_output(["g++", "--version"])
    info["node"] = command_output(["node", "--version"])
    info["emscripten"] = command_output(["emcc", "--version"])
    info["git_commit"] = command_output(["git", "rev-parse", "--short", "HEAD"])
    return info


# The figures issue 8 asks for, shown first (the full comparison follows).
HEADLINE = (r"tables_build_ms_median$", r"tables_first_use_ms$", r"\.read_and_prepare_ms$",
            r"\.bvh_build_ms_median$", r"\.queries_per_s_1_thread$", r"\.queries_per_s_total_2_threads$",
            r"^z0_median_s$", r"^voxelize_median_s$", r"^delta_e_per_s_1_thread$", r"^full_evaluation_ms_median$",
            r"^runs\[\d+\]\.(proposals_per_second|commits_per_second|proposals_per_cpu_second)$",
            r"^curves\[.*\]\.energy_(start|end)$", r"^peak_memory_mib$")


def flatten(value, prefix, out):
    """Numeric leaves as 'a.b[mesh].c'. Lists of plain numbers (curves, samples) are left out."""
    if isinstance(value, bool):
        return
    if isinstance(value, (int, float)):
        out[prefix] = value
    elif isinstance(value, dict):
        for k, v in value.items():
            flatten(v, prefix + "." + k if prefix else k, out)
    elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
        for i, v in enumerate(value):
            name = v.get("mesh", v.get("name", v.get("threads", i)))
            flatten(v, "%s[%s]" % (prefix, name), out)


def slowdown(metric, native, wasm):
    """How many times slower wasm is, when the metric says whether bigger is better."""
    if not native or not wasm:
        return None
    name = metric.lower()
    if "per_s" in name or "per_cpu_s" in name or "mb_per_s" in name or "/s" in name:
        return native / wasm
    if re.search(r"(_ms|_s|_seconds|_us)(_median)?$", name) or "_ms_" in name:
        return wasm / native
    return None


def run_name(run):
    return (run["bench"] + " " + run.get("args", "")).strip()


def comparisons(runs):
    by_key = {}
    for run in runs:
        metrics = {}
        for i, result in enumerate(run["results"]):
            flatten(result, "" if len(run["results"]) == 1 else "#%d" % i, metrics)
        by_key[(run_name(run), run["platform"])] = metrics
    rows = []
    for bench in dict.fromkeys(run_name(r) for r in runs):
        native, wasm = by_key.get((bench, "native"), {}), by_key.get((bench, "wasm"), {})
        for metric, value in native.items():
            if any(s in metric.lower() for s in SKIP):
                continue
            other = wasm.get(metric)
            ratio = other / value if other is not None and value else None
            rows.append({"bench": bench, "metric": metric, "native": value, "wasm": other,
                         "wasm_over_native": ratio, "wasm_slower_x": slowdown(metric, value, other)})
    return rows


def fmt(x):
    if x is None:
        return ""
    if isinstance(x, int) or (isinstance(x, float) and x.is_integer() and abs(x) < 1e12):
        return "{:,}".format(int(x))
    if abs(x) >= 1000:
        return "{:,.0f}".format(x)
    return "%.3g" % x


def markdown(doc):
    m = doc["machine"]
    lines = ["# Benchmarks (%s mode, %s)" % (doc["mode"], doc["date"]), "",
             "Machine: %s, %s cores, %s GiB; %s; %s; node %s; %s; load average at the end %s; commit %s." % (
                 m.get("cpu"), m.get("cores"), m.get("memory_gib"), m.get("os"), m.get("native_compiler"),
                 m.get("node"), m.get("emscripten"), m.get("load_average_at_end"), m.get("git_commit")), "",
             "## Runs (wall time and peak resident memory of the whole process, from /usr/bin/time -v)", "",
             "| bench | native s | native peak MiB | wasm s | wasm peak MiB | wasm / native time |", "|---|---|---|---|---|---|"]
    runs = {(run_name(r), r["platform"]): r for r in doc["runs"]}
    for bench in dict.fromkeys(run_name(r) for r in doc["runs"]):
        n, w = runs.get((bench, "native"), {}), runs.get((bench, "wasm"), {})
        def cell(r, k):
            if not r:
                return "not run"
            if r.get("exit_status"):
                return "failed (%d)" % r["exit_status"]
            return fmt(r.get(k))
        ratio = w.get("wall_s") / n["wall_s"] if n.get("wall_s") and w.get("wall_s") else None
        lines.append("| %s | %s | %s | %s | %s | %s |" % (bench, cell(n, "wall_s"), cell(n, "max_rss_mib"),
                                                          cell(w, "wall_s"), cell(w, "max_rss_mib"), fmt(ratio)))
    for r in doc["runs"]:
        if r["platform"] == "browser":
            metrics = {}
            for result in r["results"]:
                flatten(result, "", metrics)
            lines += ["", "## Browser (Chromium worker, Playwright; exit status %d)" % r["exit_status"], "",
                      "| metric | value |", "|---|---|"]
            lines += ["| %s | %s |" % (k, fmt(v)) for k, v in metrics.items()
                      if re.search(r"per_second|proposals|commits|seconds", k)]
    for title, rows in (("Headline figures", [r for r in doc["comparisons"]
                                                if any(re.search(h, r["metric"]) for h in HEADLINE)]),
                        ("All figures", doc["comparisons"])):
        lines += ["", "## %s (wasm slower ×: native/wasm for rates, wasm/native for times)" % title, "",
                  "| bench | metric | native | wasm | wasm slower × |", "|---|---|---|---|---|"]
        for row in rows:
            lines.append("| %s | %s | %s | %s | %s |" % (row["bench"], row["metric"], fmt(row["native"]),
                                                         fmt(row["wasm"]), fmt(row["wasm_slower_x"])))
    return "\n".join(lines) + "\n"


def report(jsonl, out_json, out_md, mode):
    with open(jsonl) as f:
        runs = [json.loads(line) for line in f if line.strip()]
    doc = {"mode": mode, "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
           "machine": machine(), "runs": runs}
    doc["comparisons"] = comparisons(runs)
    with open(out_json, "w") as f:
        json.dump(doc, f, indent=1)
    with open(out_md, "w") as f:
        f.write(markdown(doc))


def main():
    if len(sys.argv) == 8 and sys.argv[1] == "record":
        record(*sys.argv[2:])
    elif len(sys.argv) == 6 and sys.argv[1] == "report":
        report(*sys.argv[2:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
