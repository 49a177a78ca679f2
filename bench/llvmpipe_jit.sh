#!/usr/bin/env bash
# What llvmpipe makes of a shader: the machine code it generated for the hottest function of a running
# `shadelab bench` configuration (on llvmpipe, the fragment shader), disassembled, with the instructions that
# matter counted. Mesa's own dumps (GALLIVM_DEBUG=asm, LP_DEBUG=fs, NIR_DEBUG) exist only in debug builds of
# Mesa, and Debian's is a release build; so the code is read out of the process instead: perf samples
# where the process spends its time, the hottest anonymous executable mapping is llvmpipe's generated code,
# and gdb copies it out for objdump.
#
#   bench/llvmpipe_jit.sh [SHADELAB] [FILTER]
#       SHADELAB  the binary (default: build/shadelab)
#       FILTER    one `shadelab bench` configuration (default: frame/glmark2-equivalent/phong/)
#
# Prints the counts and the path of the annotated disassembly (samples per instruction in the first
# column). Needs: linux-perf, gdb, binutils, python3 (Debian packages), and ptrace rights over the child
# (root, or kernel.yama.ptrace_scope = 0).
set -euo pipefail

shadelab=${1:-build/shadelab}
filter=${2:-frame/glmark2-equivalent/phong/}

fail() {
    echo "llvmpipe_jit: $*" >&2
    exit 1
}
[[ -x $shadelab ]] || fail "no shadelab binary at '$shadelab' (pass its path as the first argument)"
for tool in perf gdb objdump python3; do
    command -v "$tool" >/dev/null || fail "$tool not found (apt-get install linux-perf gdb binutils python3)"
done

out=$(mktemp -d -t shadelab-jit-XXXXXX)
child=
cleanup() { [[ -n $child ]] && kill "$child" 2>/dev/null && wait "$child" 2>/dev/null; true; }
trap cleanup EXIT

# Enough frames to outlast the sampling; the shader cache off, so that the code is generated in this process.
MESA_SHADER_CACHE_DISABLE=true "$shadelab" bench --size 800x600 --frames 100000 --warmup 5 \
    --filter "$filter" >"$out/bench.txt" 2>&1 &
child=$!
sleep 3
kill -0 "$child" 2>/dev/null || fail "shadelab bench ended early: $(tail -3 "$out/bench.txt")"

perf record -q -e cpu-clock -F 5000 -p "$child" -o "$out/perf.data" -- sleep 2 >/dev/null 2>&1 ||
    fail "perf record failed (perf_event_paranoid? run as root)"
perf script -i "$out/perf.data" -F ip,dso >"$out/samples.txt" 2>/dev/null
cp "/proc/$child/maps" "$out/maps.txt"

# The hottest anonymous executable mapping, and the samples' addresses inside it.
python3 - "$out" <<'EOF' >"$out/region.txt"
import collections, sys
out = sys.argv[1]
regions = []
for line in open(f"{out}/maps.txt"):
    fields = line.split()
    if "x" in fields[1] and fields[4] == "0" and len(fields) == 5:  # anonymous, executable
        start, end = (int(x, 16) for x in fields[0].split("-"))
        regions.append((start, end))
hits = collections.Counter()
for line in open(f"{out}/samples.txt"):
    fields = line.split()
    if not fields: continue
    try: address = int(fields[0], 16)
    except ValueError: continue
    for start, end in regions:
        if start <= address < end:
            hits[(start, end)] += 1
if not hits: sys.exit("no samples in generated code")
(start, end), n = hits.most_common(1)[0]
total = sum(1 for line in open(f"{out}/samples.txt") if line.strip())
print(f"{start:#x} {end:#x} {n} {total}")
EOF
read -r start end hot total <"$out/region.txt"
gdb -p "$child" -batch -ex "dump memory $out/code.bin $start $end" >/dev/null 2>&1 ||
    fail "gdb could not read the process (ptrace rights?)"
kill "$child" 2>/dev/null
wait "$child" 2>/dev/null || true
child=

objdump -D -b binary -m i386:x86-64 --adjust-vma="$start" "$out/code.bin" >"$out/code.s"
python3 - "$out" "$hot" "$total" <<'EOF'
import collections, re, sys
out, hot, total = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
samples = collections.Counter()
for line in open(f"{out}/samples.txt"):
    fields = line.split()
    try: samples[int(fields[0], 16)] += 1
    except (IndexError, ValueError): pass
function, in_function = [], True  # the mapping's first function: up to its first ret
with open(f"{out}/annotated.s", "w") as annotated:
    for line in open(f"{out}/code.s"):
        m = re.match(r"\s*([0-9a-f]+):\t[0-9a-f ]+\t(.*)", line)
        if not m: continue
        address, text = int(m.group(1), 16), m.group(2)
        annotated.write(f"{samples.get(address, 0):6d}  {address:#x}  {text}\n")
        if in_function: function.append(text)
        if text.startswith("ret"): in_function = False
count = lambda pattern: sum(1 for t in function if re.match(pattern, t))
print(f"generated code: {hot} of {total} samples ({100 * hot / max(total, 1):.0f} %) in the hottest "
      f"mapping; its first function has {len(function)} instructions")
print(f"  uniform reads as bounds-checked 8-lane gathers (vpcmpltud + vpinsrd): "
      f"{count(r'vpcmpn?ltud')}")
print(f"  divisions vdivps: {count(r'vdivps')}, square roots vsqrtps: {count(r'vsqrtps')}, "
      f"fused multiply-adds: {count(r'vfmadd')}, multiplies: {count(r'vmulps')}")
print(f"annotated disassembly (samples, address, instruction): {out}/annotated.s")
EOF
