# shellcheck shell=bash
# shellcheck disable=SC2154 # $jobs and $logs are set by scripts/test.sh, which sources this file
# The stage scheduler of scripts/test.sh (sourced by it): each stage's wall and CPU time for the table printed
# at the end, and stages run in the background at a lower CPU priority, waited for by name. Expects $jobs
# (the cores) and $logs (a folder for the background stages' logs) to be set.
declare -A pids starts # the background stages: process and start time, by name
cleanup=()             # files of the run's own, removed as it ends
# ---- stage timing: a table of every stage's duration, printed at the end, whether it passed or not ----
names=()
seconds=()
cpus=() # each stage's CPU seconds: its own processes' (a foreground stage's without the background stages')
began=$(date +%s)
stage_began=$began
stage_name=""
# Sets cpu_now to the CPU seconds (user + system) of the processes this shell has waited for: `times`' second
# line, through the file $1. `times` runs in this shell, never in a pipeline or $(...): a subshell's `times`
# counts only the subshell's own children.
children_cpu() {
  times >"$1"
  cpu_now=$(tail -n 1 "$1" | awk '{ split($1, a, /[ms]/); split($2, b, /[ms]/)
    printf "%d", a[1] * 60 + a[2] + b[1] * 60 + b[2] }')
}
stage_cpu_began=0
background_cpu=0 # the CPU seconds of background stages waited for during the current stage
stage() {
  local now cpu
  now=$(date +%s)
  children_cpu "$logs/times"
  cpu=$cpu_now
  if [ -n "$stage_name" ]; then
    names+=("$stage_name")
    seconds+=($((now - stage_began)))
    cpus+=($((cpu - stage_cpu_began - background_cpu)))
  fi
  stage_name=$1
  stage_began=$now
  stage_cpu_began=$cpu
  background_cpu=0
  [ -n "$1" ] && printf '\n=== %s\n' "$1"
  return 0
}
# A stage that ran beside others: its own start and end, and its CPU seconds.
background_stage() {
  names+=("$1 (beside the others)")
  seconds+=($(($3 - $2)))
  cpus+=("$4")
  background_cpu=$((background_cpu + $4))
}
# A background stage still running when the script ends (a failure elsewhere) ends with it, children first.
kill_tree() {
  local child
  for child in $(ps -o pid= --ppid "$1" 2>/dev/null); do kill_tree "$child"; done
  kill "$1" 2>/dev/null || true
}
print_table() {
  local status=$?
  local pid
  for pid in "${pids[@]}"; do kill_tree "$pid"; done
  rm -f "${cleanup[@]}"
  stage ""
  printf '\n=== stage durations (%s, %s cores)\n' "$(date -u +%Y-%m-%dT%H:%MZ)" "$jobs"
  printf '%-72s %7s %7s\n' "" "wall" "CPU"
  for i in "${!names[@]}"; do
    printf '%-72s %4d:%02d %4d:%02d\n' "${names[$i]}" $((seconds[i] / 60)) $((seconds[i] % 60)) \
      $((cpus[i] / 60)) $((cpus[i] % 60))
  done
  # The processes' CPU time (user + system, the background stages' too), against the wall time of all cores.
  local total=$(($(date +%s) - began)) cpu
  children_cpu "$logs/times"
  cpu=$cpu_now
  printf '%-72s %4d:%02d %4d:%02d\n' "total ($jobs cores: the CPU time is at most $jobs× the wall time)" \
    $((total / 60)) $((total % 60)) $((cpu / 60)) $((cpu % 60))
  [ "$status" -eq 0 ] || printf 'FAILED (exit %d) in: %s\n' "$status" "${names[-1]:-setup}"
}

# Runs a command in the background at a lower CPU priority (the nice value NICE, 19 for the lowest), its
# output to $logs/NAME.log; `finish NAME` waits for it, prints its log if it failed, and records its duration.
#   in_background NAME NICE COMMAND...
in_background() {
  local name=$1 niceness=$2
  shift 2
  starts[$name]=$(date +%s)
  # A subshell that lowers its own priority, so that it can run this script's functions (nice cannot).
  # Its CPU seconds go to $logs/NAME.cpu (`times` in the subshell counts the subshell's children).
  (
    renice -n "$niceness" -p "$BASHPID" >/dev/null
    status=0
    "$@" || status=$?
    children_cpu "$logs/$name.times"
    echo "$cpu_now" >"$logs/$name.cpu"
    exit "$status"
  ) >"$logs/$name.log" 2>&1 &
  pids[$name]=$!
}
finish() {
  local name=$1 status=0
  wait "${pids[$name]}" || status=$?
  unset "pids[$name]"
  background_stage "$name" "${starts[$name]}" "$(date +%s)" "$(cat "$logs/$name.cpu" 2>/dev/null || echo 0)"
  if [ "$status" -ne 0 ]; then
    echo "shadelab: $name failed (exit $status); its log ($logs/$name.log):"
    tail -n 200 "$logs/$name.log"
    exit "$status"
  fi
}

