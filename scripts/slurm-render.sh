#!/usr/bin/env bash
# Renders a scene on a Slurm cluster: one job simulates the motion into a cache, a job array draws
# the frames from that cache in chunks (each task only draws), and one job assembles the movie.
# Each stage starts when the one before has succeeded (afterok); a failure cancels what follows.
#
# The cluster needs a file system that every node sees at the same paths (the usual /home or
# /scratch): the scene, its meshes, the cache and the frames live there. Paths given here are made
# absolute. dinam must run on the nodes: give --dinam, or have it on PATH there.
#
#   scripts/slurm-render.sh SCENE [--chunk N] [--partition P] [--output DIR] [--cache DIR]
#                           [--size WxH] [--movie mp4|gif] [--dinam PATH] [--time T]
#                           [--sbatch-arg ARG]... [--wait]
#
# The options are checked before anything is queued. It prints the three job ids and where the
# movie will be. Each job's log (slurm-logs/ beside the frames) says what it did, with which
# frames, and how it ended, even though dinam runs there with --quiet. --wait blocks until every
# job has ended, prints each job's (each render task's) final state, and exits 0 only if all of
# them completed, 1 otherwise (a failed chunk cancels the movie: both are named).
set -euo pipefail

usage() {
  sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
  exit 2
}

fail() {
  echo "slurm-render: $*" >&2
  exit 2
}

scene=""
chunk=20
partition=""
output=""
cache=""
size=""
movie=""
time_limit=""
wait_for_movie=false
sbatch_extra=()
here=$(cd "$(dirname "$0")" && pwd)
dinam=""
while [ $# -gt 0 ]; do
  case "$1" in
    --chunk) chunk=${2:?--chunk needs a number of frames}; shift 2 ;;
    --partition) partition=${2:?--partition needs a name}; shift 2 ;;
    --output|-o) output=${2:?--output needs a folder}; shift 2 ;;
    --cache) cache=${2:?--cache needs a folder}; shift 2 ;;
    --size) size=${2:?--size needs WxH}; shift 2 ;;
    --movie) movie=${2:?--movie needs mp4 or gif}; shift 2 ;;
    --dinam) dinam=${2:?--dinam needs the program}; shift 2 ;;
    --time) time_limit=${2:?--time needs a Slurm time limit}; shift 2 ;;
    --sbatch-arg) sbatch_extra+=("${2:?--sbatch-arg needs an argument}"); shift 2 ;;
    --wait) wait_for_movie=true; shift ;;
    -h|--help) usage ;;
    -*) fail "unknown option $1 (see --help)" ;;
    *) [ -z "$scene" ] || fail "one scene only, got '$scene' and '$1'"; scene=$1; shift ;;
  esac
done
[ -n "$scene" ] || usage
[ -f "$scene" ] || fail "no scene file '$scene'"
[[ "$chunk" =~ ^[1-9][0-9]*$ ]] || fail "--chunk takes a positive number of frames, got '$chunk'"
# The size as dinam takes it (src/app/frame_range.cpp), checked here so that a bad one fails now
# rather than in every render task once the simulation has run.
if [ -n "$size" ]; then
  [[ "$size" =~ ^([0-9]+)x([0-9]+)$ ]] && (( 10#${BASH_REMATCH[1]} >= 16 && 10#${BASH_REMATCH[1]} <= 8192 &&
    10#${BASH_REMATCH[2]} >= 16 && 10#${BASH_REMATCH[2]} <= 8192 )) ||
    fail "--size takes WIDTHxHEIGHT in pixels, each from 16 to 8192 (e.g. 1280x720), got '$size'"
fi
case "$movie" in
  ""|mp4|gif|none) ;;
  *) fail "--movie takes mp4, gif or none, got '$movie'" ;;
esac
[ -z "$time_limit" ] || [[ "$time_limit" =~ ^([0-9:-]+|UNLIMITED|unlimited|INFINITE|infinite)$ ]] ||
  fail "--time takes a Slurm time limit (minutes, MM:SS, HH:MM:SS or D-HH:MM:SS), got '$time_limit'"
command -v sbatch >/dev/null || fail "sbatch was not found: run this on a Slurm login node"

if [ -z "$dinam" ]; then
  if [ -x "$here/../build/dinam" ]; then
    dinam="$here/../build/dinam"
  else
    dinam=$(command -v dinam) || fail "no dinam program: build it (README) or give --dinam PATH"
  fi
fi
absolute() { realpath -m -- "$1"; }
dinam=$(absolute "$dinam")
scene=$(absolute "$scene")

# The scene's name, frame count and output folder, from dinam itself (this also checks the scene
# before anything is queued).
info=$("$dinam" info --json "$scene") || exit 2
json_value() { sed -n "s/^ *\"$1\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p" <<<"$info" | head -n 1; }
frames=$(json_value frame_count)
name=$(json_value name)
[ -n "$output" ] || output=$(json_value output)
output=$(absolute "$output")
[ -n "$cache" ] || cache="$output/cache"
cache=$(absolute "$cache")
chunks=$(( (frames + chunk - 1) / chunk ))
logs="$output/slurm-logs"
mkdir -p "$output" "$logs"

common=(--parsable --chdir "$output")
[ -z "$partition" ] || common+=(--partition "$partition")
[ -z "$time_limit" ] || common+=(--time "$time_limit")
common+=("${sbatch_extra[@]}")
render_options=(--movie none --quiet)
[ -z "$size" ] || render_options+=(--size "$size")
movie_options=(--quiet)
[ -z "$movie" ] || movie_options+=(--movie "$movie")

# Each job's command line, quoted for the shell that Slurm runs it in.
simulate_command=$(printf '%q ' "$dinam" simulate "$scene" -o "$cache" --quiet)
render_command=$(printf '%q ' "$dinam" render "$scene" --cache "$cache" -o "$output" \
  "${render_options[@]}")
movie_command=$(printf '%q ' "$dinam" movie "$output" "${movie_options[@]}")

# A job's script: a line saying what it does and where, the command, and a line saying how it
# ended and how long it took, so that its log says something though dinam is quiet. LABEL may
# hold shell expansions for the job's shell (the chunk's frames).
logged() {  # LABEL COMMAND
  printf 'echo "%s: started on $(hostname) at $(date -u +%%FT%%TZ)"; start=$SECONDS; %s; ' "$1" "$2"
  printf 'status=$?; echo "%s: ended with status $status after $(( SECONDS - start )) s"; ' "$1"
  printf 'exit $status'
}

simulate_job=$(sbatch "${common[@]}" --job-name "dinam-simulate-$name" \
  --output "$logs/simulate-%j.log" \
  --wrap "$(logged "simulate $name into $cache" "$simulate_command")")
render_job=$(sbatch "${common[@]}" --job-name "dinam-render-$name" \
  --dependency "afterok:$simulate_job" --kill-on-invalid-dep=yes --array "0-$((chunks - 1))" \
  --output "$logs/render-%A_%a.log" \
  --wrap "first=\$(( SLURM_ARRAY_TASK_ID * $chunk + 1 )); last=\$(( first + $chunk - 1 )); \
if [ \$last -gt $frames ]; then last=$frames; fi; \
$(logged "render chunk \$SLURM_ARRAY_TASK_ID of $chunks, frames \$first-\$last of $frames" \
  "$render_command --frames \$first-\$last")")
echo "slurm-render: simulate job $simulate_job; render array $render_job ($chunks tasks of up to \
$chunk frames, $frames in all); movie job follows"
movie_job=$(sbatch "${common[@]}" --job-name "dinam-movie-$name" \
  --dependency "afterok:${render_job%%;*}" --kill-on-invalid-dep=yes \
  --output "$logs/movie-%j.log" --wrap "$(logged "movie of $name" "$movie_command")")
extension=${movie:-$(json_value movie)}
[ "$extension" != none ] || extension=mp4
echo "slurm-render: movie job $movie_job; the movie will be $output/$name.$extension, beside the \
frames; logs in $logs, the cache in $cache"
$wait_for_movie || exit 0

# --wait: until none of the jobs is queued or running, then each one's final state from the
# controller (which keeps ended jobs for MinJobAge, 300 s by default; no accounting needed).
jobs="${simulate_job%%;*},${render_job%%;*},${movie_job%%;*}"
while [ -n "$(squeue -h -j "$jobs" -o %i 2>/dev/null)" ]; do
  sleep 1
done
failed=0
while read -r line; do
  id=$(sed -n 's/^JobId=\([0-9]*\).*/\1/p' <<<"$line")
  task=$(sed -n 's/.* ArrayTaskId=\([0-9]*\).*/\1/p' <<<"$line")
  job_name=$(sed -n 's/.* JobName=\([^ ]*\).*/\1/p' <<<"$line")
  state=$(sed -n 's/.* JobState=\([^ ]*\).*/\1/p' <<<"$line")
  reason=$(sed -n 's/.* Reason=\([^ ]*\).*/\1/p' <<<"$line")
  exit_code=$(sed -n 's/.* ExitCode=\([^ ]*\).*/\1/p' <<<"$line")
  what="${job_name%-"$name"}${task:+ task $task} (job $id)"
  if [ "$state" = COMPLETED ]; then
    echo "slurm-render: $what: COMPLETED"
  else
    failed=1
    echo "slurm-render: $what: $state, exit code $exit_code, reason $reason" >&2
  fi
done < <(for job in ${jobs//,/ }; do scontrol -o show job "$job"; done)
if [ $failed -ne 0 ]; then
  echo "slurm-render: the render did not complete; see the logs in $logs" >&2
  exit 1
fi
echo "slurm-render: every job completed; the movie is $output/$name.$extension"
