#!/usr/bin/env bash
# shadelab's shading modes beside glmark2's `shading` scenes, on the same GL driver in one run, as
# frame-time ratios (issue 5, item 4). See bench/README.md for what is matched and what is not.
#
#   bench/compare_glmark2.sh [SHADELAB]        SHADELAB: the binary (default: build/shadelab)
#
# Environment: ROUNDS (default 3) rounds; in each, every mode is measured as a pair run back to back —
# glmark2 on the same sphere for DURATION seconds (default 4), then shadelab for FRAMES timed frames
# (default 800, about as long) — so that both halves of a pair see the same machine: on a shared VM the
# speed drifts by more than the differences measured here from one ten-second stretch to the next. Each
# ratio is the median over the rounds of the pairs' ratios (min–max beside it). Each round also runs
# glmark2's cat and shadelab's limits. KEEP=1 keeps the temporary folder, PIN=1 pins llvmpipe's rasterizer
# threads of both programs one to a CPU (llvmpipe-N to CPU N mod the CPU count): the scheduler otherwise
# queues both on one CPU in some frames, a tail both programs share (bench/README.md "The frame-time tail,
# and pinned threads").
#
# Needs: glmark2-x11, xvfb, python3 (Debian packages). Starts its own Xvfb on a free display.
set -euo pipefail

shadelab=${1:-build/shadelab}
duration=${DURATION:-4}
frames=${FRAMES:-800}
rounds=${ROUNDS:-3}
pin=${PIN:-0}

fail() {
    echo "compare_glmark2: $*" >&2
    exit 1
}
[[ -x $shadelab ]] || fail "no shadelab binary at '$shadelab' (pass its path as the first argument)"
[[ $pin == 0 || $pin == 1 ]] || fail "PIN is '$pin': set it to 1 (pin llvmpipe's threads) or 0 (the default)"
for tool in glmark2 Xvfb python3; do
    command -v "$tool" >/dev/null || fail "$tool not found (apt-get install glmark2-x11 xvfb python3)"
done

tmp=$(mktemp -d -t shadelab-glmark2-XXXXXX)
xvfb_pid=
cleanup() {
    [[ -n $xvfb_pid ]] && kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null
    if [[ ${KEEP:-0} == 1 ]]; then echo "kept $tmp"; else rm -rf "$tmp"; fi
}
trap cleanup EXIT

# Xvfb picks a free display itself and writes its number once it accepts connections.
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb_pid=$!
for _ in $(seq 100); do
    [[ -s $tmp/display ]] && break
    kill -0 "$xvfb_pid" 2>/dev/null || fail "Xvfb did not start: $(cat "$tmp/xvfb.log")"
    sleep 0.1
done
[[ -s $tmp/display ]] || fail "Xvfb gave no display number within 10 s"
display=:$(head -n1 "$tmp/display")

# glmark2 frames any model from its bounding box (src/scene-shading.cpp upstream): r = half the box's
# diagonal, the model's centre at distance 2 + r, fovy = 2·atan(r/(2 + r)), near 2, far 2 + 2r. It is handed
# shadelab's level-6 sphere as a model (below), so both programs draw the same 16,384 faces at the same
# coverage; its cat is measured as well, as glmark2 ships it.
#
# The sphere as DESIGN §1 builds it (the tetrahedron, each triangle split into (a,ab,ac), (ab,b,bc),
# (bc,c,ac), (ab,bc,ac), midpoints numbered on first use, normalized as glm::normalize does): the vertices
# and triangles of shadelab's mesh in its order, written as float text (9 significant digits round-trip a
# float) — byte for byte the file buildSphere(6)'s positions and triangles give, printed the same way.
# glmark2 computes its own vertex normals (averaged, as shadelab's).
glmark2_data=${GLMARK2_DATA:-/usr/share/glmark2}
[[ -d $glmark2_data/shaders ]] || fail "no glmark2 data at '$glmark2_data' (set GLMARK2_DATA to its folder)"
mkdir -p "$tmp/glmark2-data/models"
for part in shaders textures; do ln -s "$glmark2_data/$part" "$tmp/glmark2-data/$part"; done
ln -s "$glmark2_data/models/cat.3ds" "$tmp/glmark2-data/models/cat.3ds"
python3 - "$tmp/glmark2-data/models/shadelab-sphere.obj" <<'EOF'
import math, sys
s2, s6 = math.sqrt(2), math.sqrt(6)
points = [(0, 0, 1), (0, 2 * s2 / 3, -1 / 3), (-s6 / 3, -s2 / 3, -1 / 3), (s6 / 3, -s2 / 3, -1 / 3)]
triangles = [(3, 2, 1), (0, 1, 2), (0, 3, 1), (0, 2, 3)]
for level in range(6):
    midpoints = {}
    def midpoint(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoints:
            m = [(points[a][i] + points[b][i]) / 2 for i in range(3)]
            inverse = 1 / math.sqrt((m[0] * m[0] + m[1] * m[1]) + m[2] * m[2])  # as glm::normalize
            points.append(tuple(c * inverse for c in m))
            midpoints[key] = len(points) - 1
        return midpoints[key]
    split = []
    for a, b, c in triangles:
        ab, bc, ac = midpoint(a, b), midpoint(b, c), midpoint(a, c)
        split += [(a, ab, ac), (ab, b, bc), (bc, c, ac), (ab, bc, ac)]
    triangles = split
assert (len(points), len(triangles)) == (8194, 16384)
with open(sys.argv[1], "w") as out:
    out.writelines("v %.9g %.9g %.9g\n" % p for p in points)
    out.writelines("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in triangles)
EOF

# The shadelab scene of `shadelab bench`'s frame/glmark2-equivalent/phong, written out to check its coverage
# independently: glmark2's framing of the unit sphere (r = √3, its box being [−1, 1]³ to within 1e-3), a
# silhouette of 179.8 px radius of 600.
python3 - "$tmp/scene.json" <<'EOF'
import json, math, sys
r = math.sqrt(3)
d = 2 + r
fovy = math.degrees(2 * math.atan(r / d))
scene = {
    "image": {"width": 800, "height": 600, "background": [1, 0, 1]},
    "camera": {"eye": [0, 0, d], "target": [0, 0, 0], "up": [0, 1, 0]},
    "projection": {"type": "perspective", "fovy_deg": fovy, "near": 2, "far": 2 + 2 * r},
    "shading": "phong", "lighting": "phong",
    "objects": [{"center": [0, 0, 0], "radius": 1, "subdivisions": 6,
                 "material": {"ambient": [0.2] * 3, "diffuse": [0, 0, 1], "specular": [1, 1, 1],
                              "shininess": 100}}],
    "lights": [{"type": "point", "position": [0, 1, d], "ambient": [0.1] * 3, "diffuse": [0.8] * 3,
                "specular": [0.8] * 3, "attenuation": [1, 0, 0]}],
}
json.dump(scene, open(sys.argv[1], "w"), indent=2)
EOF
"$shadelab" render "$tmp/scene.json" --out "$tmp/coverage.png" >/dev/null

# PIN=1: a launcher that pins each llvmpipe-N thread as it appears, then waits for the program. Both programs
# are started through it (with PIN=0 it only runs them).
cat >"$tmp/launch.py" <<'EOF'
import os, subprocess, sys, time
pin, command = sys.argv[1] == "1", sys.argv[2:]
child = subprocess.Popen(command)
pinned, cpus = set(), os.cpu_count() or 1
while pin and len(pinned) < cpus and child.poll() is None:
    try:
        tids = os.listdir(f"/proc/{child.pid}/task")
    except FileNotFoundError:
        break
    for tid in tids:
        try:
            name = open(f"/proc/{child.pid}/task/{tid}/comm").read().strip()
        except OSError:
            continue
        if tid not in pinned and name.startswith("llvmpipe-") and name[9:].isdigit():
            os.sched_setaffinity(int(tid), {int(name[9:]) % cpus})
            pinned.add(tid)
    time.sleep(0.005)
sys.exit(child.wait())
EOF
launch=(python3 "$tmp/launch.py" "$pin")

modes=(gouraud blinn-phong-inf phong cel)
# glmark2 with the given -b benchmarks, its output in $1.
run_glmark2() {
    local out=$1
    shift
    DISPLAY=$display "${launch[@]}" glmark2 --data-path "$tmp/glmark2-data" --off-screen -s 800x600 "$@" \
        >"$out" 2>&1 || fail "glmark2 failed: $(tail -5 "$out")"
    grep -q "FrameTime" "$out" || fail "glmark2 printed no frame times: $(tail -5 "$out")"
}
# shadelab bench of the configurations $2 matches, its JSON in $1.json.
run_shadelab() {
    "${launch[@]}" "$shadelab" bench --size 800x600 --frames "$frames" --filter "$2" --json "$1.json" \
        >"$1.txt" 2>&1 || fail "shadelab bench failed: $(tail -5 "$1.txt")"
}

for round in $(seq "$rounds"); do
    echo "round $round/$rounds: clear and each mode, glmark2 ${duration} s then shadelab ${frames} frames ..." >&2
    run_glmark2 "$tmp/glmark2-$round-clear.txt" -b "clear:duration=$duration"
    run_shadelab "$tmp/shadelab-$round-clear" 'frame/limits/clear/'
    for mode in "${modes[@]}"; do
        run_glmark2 "$tmp/glmark2-$round-$mode.txt" \
            -b "shading:shading=$mode:model=shadelab-sphere:duration=$duration"
        # phong's run times the one-colour culled sphere too: the two in one process, one moment.
        extra=""
        if [[ $mode == phong ]]; then extra="|one-colour-culled"; fi
        run_shadelab "$tmp/shadelab-$round-$mode" "frame/glmark2-equivalent/($mode$extra)/"
    done
    echo "round $round/$rounds: glmark2's cat, shadelab's limits ..." >&2
    cat_benchmarks=()
    for mode in "${modes[@]}"; do cat_benchmarks+=(-b "shading:shading=$mode:model=cat:duration=$duration"); done
    run_glmark2 "$tmp/glmark2-$round-cat.txt" "${cat_benchmarks[@]}"
    run_shadelab "$tmp/shadelab-$round-limits" 'frame/(glmark2-equivalent/one-colour(-culled)?|limits/fill)/'
done

python3 - "$tmp" "$rounds" "$duration" "$pin" "$frames" <<'EOF'
import json, re, statistics, sys, zlib

tmp, rounds, duration, pin, frames = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4] == "1", sys.argv[5]

def png_rgb(path):
    """The pixels of shadelab's 8-bit RGB PNG (non-interlaced), as rows of bytes."""
    data = open(path, "rb").read()
    pos, idat, width, height, channels = 8, b"", 0, 0, 3
    while pos < len(data):
        length = int.from_bytes(data[pos:pos + 4], "big")
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height = int.from_bytes(body[0:4], "big"), int.from_bytes(body[4:8], "big")
            channels = {2: 3, 6: 4}[body[9]]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = previous[x], previous[x - channels] if x >= channels else 0
            if kind == 1: line[x] = (line[x] + a) & 255
            elif kind == 2: line[x] = (line[x] + b) & 255
            elif kind == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows

width, height, channels, rows = png_rgb(f"{tmp}/coverage.png")
covered = sum(1 for row in rows for x in range(0, len(row), channels)
              if tuple(row[x:x + 3]) != (255, 0, 255))  # the scene's background is magenta

def glmark2_times(path):
    """{(mode or benchmark, model): frame time in ms} of one glmark2 output."""
    times = {}
    for line in open(path):
        m = re.match(r"\[(\w+)\] (.*): FPS: \d+ FrameTime: ([\d.]+) ms", line)
        if m:
            mode, model = re.search(r"shading=([\w-]+)", m.group(2)), re.search(r"model=([\w-]+)", m.group(2))
            times[(mode.group(1), model.group(1)) if mode else (m.group(1), None)] = float(m.group(3))
    return times

def shadelab_results(stem):
    report = json.load(open(f"{stem}.json"))
    return report["renderer"], report["results"]

equivalent = "frame/glmark2-equivalent/"
rows = [("clear", "clear", "frame/limits/clear"),
        ("gouraud", "gouraud (directional light, diffuse only)", equivalent + "gouraud"),
        ("blinn-phong-inf", "phong shading, blinn-phong, directional", equivalent + "blinn-phong-inf"),
        ("phong", "phong shading, phong, point light", equivalent + "phong"),
        ("cel", "toon, 2 bands, point light", equivalent + "cel")]
pairs = {g: [] for g, _, _ in rows}  # per round: (glmark2 ms, shadelab mean ms, shadelab median ms)
cat, limits, covered_px, phong_over_culled = {g: [] for g, _, _ in rows[1:]}, {}, [], []
for r in range(1, rounds + 1):
    for g, _, name in rows:
        key = ("clear", None) if g == "clear" else (g, "shadelab-sphere")
        renderer, results = shadelab_results(f"{tmp}/shadelab-{r}-{g}")
        figures = results[name]
        pairs[g].append((glmark2_times(f"{tmp}/glmark2-{r}-{g}.txt")[key], figures["mean_ms"],
                         figures["median_ms"]))
        if g == "phong":
            covered_px.append(figures["covered_px"])
            phong_over_culled.append(figures["mean_ms"] / results[equivalent + "one-colour-culled"]["mean_ms"])
    cat_times = glmark2_times(f"{tmp}/glmark2-{r}-cat.txt")
    for g in cat:
        cat[g].append(cat_times[(g, "cat")])
    for name, figures in shadelab_results(f"{tmp}/shadelab-{r}-limits")[1].items():
        limits.setdefault(name, []).append(figures)

med = statistics.median
print(f"\nshadelab: {renderer}; glmark2 under Xvfb, --off-screen (glFinish per frame, as shadelab), 800x600")
print(f"coverage: shadelab's render of the equivalent scene covers {covered} px "
      f"({100 * covered / (width * height):.1f} % of {width}x{height}; the bench counted "
      f"{med(covered_px):.0f} px); glmark2 frames the same sphere the same way (179.8 px radius); its cat "
      f"covers about 15-20 %")
print(f"frame times in ms, medians over {rounds} round(s): glmark2's mean over {duration} s, shadelab's mean "
      f"(median) over {frames} frames run straight after it; ratio = shadelab mean / glmark2 mean of the "
      f"same round, median (min-max) over the rounds"
      + ("; llvmpipe's threads pinned one to a CPU in both (PIN=1)" if pin else "") + "\n")
print(f"{'':<16} {'glmark2, same sphere':>21}   {'shadelab':<42} {'ms':>6} {'(median)':>9}"
      f"  {'ratio':>6} {'(min-max)':>12}   {'glmark2 cat':>11}  {'ratio':>6}")
for g, label, name in rows:
    gs, sm, sd = (med(p[i] for p in pairs[g]) for i in range(3))
    ratios = [p[1] / p[0] for p in pairs[g]]
    spread = f"({min(ratios):.2f}-{max(ratios):.2f})"
    gc = med(cat[g]) if g in cat else gs
    print(f"{g:<16} {gs:18.2f} ms   {label:<42} {sm:6.2f} {f'({sd:.2f})':>9}  {med(ratios):6.2f} {spread:>12}"
          f"   {gc:8.2f} ms  {sm / gc:6.2f}")
print("\nshadelab's limits for this geometry (no lighting), medians over the rounds:")
for label, name in [("full-screen fill, 800x600", "frame/limits/fill"),
                    ("one-colour sphere, back faces drawn", equivalent + "one-colour"),
                    ("one-colour sphere, back faces culled (as shadelab and glmark2)",
                     equivalent + "one-colour-culled")]:
    print(f"  {label:<58} {med(f['mean_ms'] for f in limits[name]):7.2f} ms  fragments/covered px "
          f"{med(f['fragments_per_px'] for f in limits[name]):.2f}")
print(f"  phong frame / one-colour culled sphere, both in phong's shadelab run: {med(phong_over_culled):.2f} "
      f"({min(phong_over_culled):.2f}-{max(phong_over_culled):.2f})")
EOF
