"""What ``--agent consensus`` runs measure: the consensus answer's accuracy against the accuracy of
the same samples taken one at a time, and accuracy per confidence bin (is the confidence a
probability of being right?). Pure functions of task records.

"Right" is the paper's verdict (``overall``) and, beside it, the behaviour verdict: the samples are
grouped by behaviour, so the behaviour verdict is what the confidence speaks about most directly.
"""

from __future__ import annotations

from typing import Any

from meceng.eval.rates import Rate, Run

#: Upper edges of the confidence bins (a bin holds confidences in (previous edge, edge]).
BIN_EDGES = (0.2, 0.4, 0.6, 0.8, 1.0)


def consensus_records(tasks: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Graded consensus records (a task lost to the server is left out, as in every rate)."""
    return [t for t in tasks if isinstance(t.get("consensus"), dict) and t.get("first_failure") != "infrastructure"]


def _behaves(block: dict[str, Any]) -> bool:
    return bool((block.get("behaviour") or {}).get("passed")) if "behaviour" in block else bool(
        block.get("behaviour_passed"))


def accuracy(tasks: list[dict[str, Any]]) -> dict[str, Rate]:
    """Consensus and single-sample accuracy, by the paper's and by the behaviour verdict. A single
    sample's accuracy pools every graded sample (the mean over samples); a sample the server lost
    is not counted."""
    records = consensus_records(tasks)
    samples = [s for t in records for s in t["consensus"].get("samples", [])
               if s.get("lost") is None and "overall" in s]
    return {"consensus": Rate(sum(bool(t.get("overall")) for t in records), len(records)),
            "single": Rate(sum(bool(s["overall"]) for s in samples), len(samples)),
            "consensus_behaviour": Rate(sum(_behaves(t) for t in records), len(records)),
            "single_behaviour": Rate(sum(_behaves(s) for s in samples), len(samples))}


def calibration(tasks: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Per confidence bin: how many answers, their mean confidence and how often they were right."""
    rows = []
    records = consensus_records(tasks)
    low = 0.0
    for edge in BIN_EDGES:
        inside = [t for t in records if low < float(t["consensus"]["confidence"]) <= edge + 1e-9]
        mean = sum(float(t["consensus"]["confidence"]) for t in inside) / len(inside) if inside else None
        rows.append({"bin": f"({low:.1f}, {edge:.1f}]", "n": len(inside), "confidence": mean,
                     "paper": Rate(sum(bool(t.get("overall")) for t in inside), len(inside)),
                     "behaviour": Rate(sum(_behaves(t) for t in inside), len(inside))})
        low = edge
    return rows


def calibration_error(rows: list[dict[str, Any]], verdict: str = "paper") -> float | None:
    """The expected calibration error: the bins' |accuracy - mean confidence|, weighted by their
    share of the answers (0: the confidence is the probability of being right)."""
    total = sum(r["n"] for r in rows)
    if not total:
        return None
    return sum(r["n"] / total * abs((r[verdict].value or 0.0) - r["confidence"]) for r in rows if r["n"])


def per_model(tasks: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """A consensus run across models (``--consensus-models``): per model, its samples' accuracy taken
    one at a time and how many answers it wrote (the chosen sample was its); empty for a run whose
    samples one model wrote. Lost samples are not counted."""
    records = consensus_records(tasks)
    samples = [s for t in records for s in t["consensus"].get("samples", []) if s.get("lost") is None]
    models = list(dict.fromkeys(str(s["model"]) for s in samples if s.get("model")))
    if len(models) < 2:
        return []
    answers = [next((s for s in t["consensus"].get("samples", []) if s.get("index") == t["consensus"].get("chosen")),
                    {}) for t in records]
    rows = []
    for model in models:
        own = [s for s in samples if s.get("model") == model and "overall" in s]
        rows.append({"model": model, "paper": Rate(sum(bool(s["overall"]) for s in own), len(own)),
                     "behaviour": Rate(sum(_behaves(s) for s in own), len(own)),
                     "answers": Rate(sum(a.get("model") == model for a in answers), len(records))})
    return rows


def consensus_table(runs: list[Run]) -> list[dict[str, Any]]:
    """One row per consensus run: both accuracies, both verdicts, the calibration error."""
    rows = []
    for run in runs:
        if not consensus_records(run.tasks):
            continue
        bins = calibration(run.tasks)
        rows.append({"run": run.label, "samples": run.settings.get("pipeline", {}).get("samples"),
                     **accuracy(run.tasks), "bins": bins, "models": per_model(run.tasks),
                     "ece_paper": calibration_error(bins),
                     "ece_behaviour": calibration_error(bins, "behaviour")})
    return rows


def consensus_sections(runs: list[Run]) -> list[tuple[str, list[str], list[list[str]]]]:
    """The report's consensus tables (title, headers, rows): accuracy, then calibration per bin."""
    table = consensus_table(runs)
    if not table:
        return []

    def ece(value: float | None) -> str:
        return "–" if value is None else f"{value:.3f}"

    accuracy_rows = [[r["run"], str(r["samples"]), str(r["consensus"].n), r["consensus"].text(), r["single"].text(),
                      r["consensus_behaviour"].text(), r["single_behaviour"].text(), ece(r["ece_paper"]),
                      ece(r["ece_behaviour"])] for r in table]
    bin_rows = [[r["run"], b["bin"], str(b["n"]), "–" if b["confidence"] is None else f"{b['confidence']:.2f}",
                 b["paper"].text(), b["behaviour"].text()] for r in table for b in r["bins"] if b["n"]]
    model_rows = [[r["run"], m["model"], str(m["paper"].n), m["paper"].text(), m["behaviour"].text(),
                   m["answers"].text()] for r in table for m in r["models"]]
    across = [("Consensus across models: each model's samples one at a time, and the answers it wrote",
               ["run", "model", "samples", "right (paper)", "right (behaviour)", "answers written"], model_rows)]
    return [("Consensus: the answer of the largest group against single samples (levels 1-2)",
             ["run", "K", "tasks", "consensus (paper)", "single sample (paper)", "consensus (behaviour)",
              "single sample (behaviour)", "calibration error (paper)", "calibration error (behaviour)"],
             accuracy_rows),
            ("Consensus: accuracy per confidence bin (calibrated: accuracy = mean confidence)",
             ["run", "confidence", "tasks", "mean confidence", "right (paper)", "right (behaviour)"], bin_rows),
            *(across if model_rows else [])]
