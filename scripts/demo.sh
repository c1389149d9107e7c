#!/usr/bin/env bash
# The main job on embedded (generated) demo data, entirely through qgis_process:
#   1. generate the demo LiDAR tile and check points (deterministic, no downloads);
#   2. GSD / photogrammetric accuracy for the paper's camera;
#   3. LiDAR chain: ground filter (geomatics:groundfilter, the recommended one, inside the
#      shipped model) → DTM → accuracy against the check points;
#   4. a 4-tile catalog processed in buffered chunks on a local Dask cluster.
# Outputs go to the folder given as $1 (default out/).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
PY="$ROOT/.venv/bin/python"
OUT="${1:-out}"
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$TMP/plugins" "$TMP/profile"
ln -s "$ROOT" "$TMP/plugins/geomatics_toolbox"
export QGIS_CUSTOM_CONFIG_PATH="$TMP/profile" QGIS_PLUGINPATH="$TMP/plugins"
export QT_QPA_PLATFORM=offscreen
# qgis_process runs the system Python: let it see the venv's laspy/lazrs/pykrige
SITE="$("$PY" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
export PYTHONPATH="$SITE${PYTHONPATH:+:$PYTHONPATH}"
QP=qgis_process.bin
$QP plugins enable geomatics_toolbox >/dev/null

run() {  # run ALG NAME PARAMS... : JSON to $OUT/NAME.json, fails loudly
  local alg="$1" name="$2"; shift 2
  echo "== $alg → $OUT/$name.json"
  if ! $QP --json run "$alg" -- "$@" > "$OUT/$name.json" 2> "$TMP/err.txt"; then
    cat "$TMP/err.txt" "$OUT/$name.json" >&2
    echo "demo: $alg failed" >&2
    exit 1
  fi
}

echo "== demo data → $OUT/demo"
"$PY" "$ROOT/scripts/make_demo_data.py" --out "$OUT/demo"

run geomatics:gsdcalculator gsd DISTANCE=5.88 SENSOR_WIDTH=6.123 IMAGE_WIDTH=3648 \
  FOCAL_LENGTH=4.6 TARGET_GSD=0.21 OBSERVED_SXYZ=3.85 OUTPUT_HTML="$OUT/gsd_report.html"

run geomatics:lidar_to_dtm lidar_to_dtm INPUT="$OUT/demo/demo.laz" \
  CHECKPOINTS_CSV="$OUT/demo/checkpoints.csv" CELL_SIZE=1 POWER=3 \
  "publish:Classified point cloud=$OUT/demo_classified.laz" \
  "publish:Ground filter report=$OUT/ground_filter_report.html" \
  "publish:DTM=$OUT/dtm_idw.tif" "publish:DTM report=$OUT/dtm_report.html" \
  "publish:Check-point residuals=$OUT/checkpoint_residuals.gpkg" \
  "publish:DTM accuracy report=$OUT/dtm_accuracy_report.html"

# the accuracy numbers again as outputs (models in QGIS 3.22 expose only file outputs)
run geomatics:dtmaccuracy dtm_accuracy DTM="$OUT/dtm_idw.tif" \
  CHECKPOINTS_CSV="$OUT/demo/checkpoints.csv"

# the filter's own accuracy: the demo tile carries its true classes (2 = ground)
run geomatics:groundfilteraccuracy ground_filter_accuracy INPUT="$OUT/demo_classified.laz" \
  REFERENCE="$OUT/demo/demo.laz" OUTPUT_HTML="$OUT/ground_filter_accuracy.html"

# a small tile catalog: 4 adjacent generated tiles, buffered chunks on a local Dask cluster
mkdir -p "$OUT/catalog_tiles"
"$PY" - "$OUT/catalog_tiles" <<'PYEOF'
import sys
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
for i in range(2):
    for j in range(2):
        t = generate_tile(extent=(250.0, 250.0), origin=(500000.0 + 250 * i, 4000000.0 + 250 * j),
                          density=0.8, seed=10 * i + j)
        write_tile(t, f"{sys.argv[1]}/tile_{i}{j}.laz")
PYEOF
run geomatics:catalog catalog INPUT="$OUT/catalog_tiles" CELL_SIZE=2 BUFFER=120 WORKERS=2 \
  OUTPUT_FOLDER="$OUT/catalog" OUTPUT_HTML="$OUT/catalog_report.html"

"$PY" - "$OUT" <<'PYEOF'
import json, sys, pathlib
out = pathlib.Path(sys.argv[1])
for f in sorted(out.glob("*.json")):
    text = f.read_text()
    res = json.loads(text[text.find("{"):]).get("results", {})
    nums = {k: float(f"{v:.6g}") for k, v in res.items() if isinstance(v, float)}
    files = {k: v for k, v in res.items() if isinstance(v, str)}
    print(f"{f.stem}: {nums or ''} {files or ''}")
    data = json.loads(text[text.find("{"):])
    for line in data.get("log", {}).get("info", []) if isinstance(data.get("log"), dict) else []:
        if "RMSE" in line:
            print("   ", line.strip())
PYEOF
echo "demo: all outputs in $OUT"
