"""The table of the transition speed series from its result directories (README.md): one row per complete run."""
import json, os, sys
root = sys.argv[1] if len(sys.argv) > 1 else "results/transition_crack_friction"
rows = {}
for d in sorted(os.listdir(root)):
    p = os.path.join(root, d, "summary.json")
    if not d.startswith("v") or not os.path.isfile(p):
        continue
    s = json.load(open(p))
    if s.get("status") != "complete":
        continue
    v = float(d[1:d.index("mps")]); n = int(d.split("_n")[1])
    c, ot = s["chip"], s["chip_over_time"]
    cls = ", ".join(f"{k} {v}" for k, v in sorted(ot["classifications"].items()))
    gs = ot["segmentation_degree"]
    pitch = c.get("pitch_m")
    rows[(n, v)] = (f"| t0/{n} | {v:g} | {c['classification']}"
                    f"{' (' + c['classification_confidence'] + ')' if c.get('classification_confidence') == 'marginal' else ''}, "
                    f"{c['pieces']} piece{'s' if c['pieces'] != 1 else ''} | {cls} of {gs['samples']} | {gs['mean']:.2f} ({gs['min']:.2f}–{gs['max']:.2f}) | "
                    f"{'%.0f' % (pitch * 1e6) if pitch else '–'} | {s['mean_cutting_force_N_per_mm']:.1f} | {s['mean_thrust_force_N_per_mm']:.1f} | "
                    f"{c['chip_thickness_ratio']:.2f} | {s['max_temperature_K']:.0f} | {s['mass_scaling']['factor']:.3g} | {s['wall_time_s']:.0f} |")
print("| grid | V (m/s) | final chip | steady samples | Gs mean (min–max) | pitch (µm) | Fc (N/mm) | Ft (N/mm) | t0/tc | max T (K) | mass scaling | wall (s) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for k in sorted(rows):
    print(rows[k])
