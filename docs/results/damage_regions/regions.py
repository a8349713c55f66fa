#!/usr/bin/env python3
"""Where the damage dissipation sits, and how it scales with the cell (issue 11, item 3).

Reads the run records (summary.json and scene.toml of complete runs) of the measured condition with penalty
contact (../penalty_contact/records, grid phase 0, t0/10, t0/16, t0/24) and of the default cut with penalty contact
(records/ beside this script, 12, 8 and 6 µm), and writes damage_regions.csv and damage_regions.md beside it.
For each region of summary.json `fracture.regions` (docs/analysis.md) it gives the damage dissipation (J/m), the
crack length it stands for (dissipation / G_f, mm) and the dissipation per unit initial volume of the region's
particles (MJ/m^3: dissipation / (particles x (h / n)^2), n particles per cell and direction). A dissipation that
belongs to cracks keeps its crack length as the cell shrinks (its density grows as 1/h); one smeared over a region
of fixed physical size keeps its density and its crack length; one spread over a layer of fixed cell count keeps
its density and loses its crack length in proportion to h.
Run: /usr/bin/python3 docs/results/damage_regions/regions.py
"""
import csv
import json
import pathlib
import tomllib

here = pathlib.Path(__file__).resolve().parent
RUNS = [
    ("measured condition (h 0.1 mm, 100 m/min, r_n 34.4 µm), penalty", here.parent / "penalty_contact" / "records",
     ["penalty_t0-10_phase0", "penalty_t0-16_phase0", "penalty_t0-24_phase0"]),
    ("default cut (20 m/s, r_n 5 µm, 0.2 mm of cut), penalty", here / "records",
     ["default_cut_penalty_12um", "default_cut_penalty_8um", "default_cut_penalty_6um"]),
]
REGIONS = ["chip_free_surface_layer", "chip_interior", "chip_fragments", "workpiece"]


def rows():
    for condition, folder, names in RUNS:
        for name in names:
            d = folder / name
            s = json.loads((d / "summary.json").read_text())
            scene = tomllib.loads((d / "scene.toml").read_text())
            h = scene["grid"]["cell_size"]
            n = scene["body"][0]["particles_per_cell"]
            f = s["fracture"]
            r = {"condition": condition, "record": name, "cell_um": round(h * 1e6, 2),
                 "damage_share_of_tool_work": round(f["energy_partition"]["damage"], 3),
                 "equivalent_crack_mm": round(f["equivalent_crack_length_mm"], 3),
                 "new_surface_mm": round(f["new_surface_length_mm"], 3),
                 "equivalent_over_new": round(f["equivalent_crack_length_mm"] / f["new_surface_length_mm"], 2)}
            for region in REGIONS:
                g = f["regions"][region]
                volume = g["particles"] * (h / n) ** 2
                r[f"{region}_J_per_m"] = round(g["damage_dissipation_J_per_m"], 2)
                r[f"{region}_crack_mm"] = round(g["equivalent_crack_length_mm"], 3)
                r[f"{region}_MJ_per_m3"] = round(g["damage_dissipation_J_per_m"] / volume / 1e6, 1) if volume else ""
                r[f"{region}_particles"] = g["particles"]
            yield r


def main():
    table = list(rows())
    with open(here / "damage_regions.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table)
    lines = ["| condition | cell (µm) | damage / W | equivalent crack / new surface (mm) | free-surface layer: J/m, "
             "crack mm, MJ/m³ | chip interior: J/m, crack mm, MJ/m³ | workpiece: J/m, crack mm, MJ/m³ |",
             "|---|---|---|---|---|---|---|"]
    for r in table:
        cells = [f"{r[f'{g}_J_per_m']}, {r[f'{g}_crack_mm']}, {r[f'{g}_MJ_per_m3']}"
                 for g in ("chip_free_surface_layer", "chip_interior", "workpiece")]
        lines.append(f"| {r['condition']} | {r['cell_um']} | {r['damage_share_of_tool_work']} | "
                     f"{r['equivalent_crack_mm']} / {r['new_surface_mm']} ({r['equivalent_over_new']}) | "
                     + " | ".join(cells) + " |")
    (here / "damage_regions.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
