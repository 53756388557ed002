#!/usr/bin/env bash
# Strong scaling of subd-mpi on this machine: the same mesh and scheme on 1 and 2 ranks (and
# more if asked), each run best of 3. Prints, per rank count, the time to cut out the piece and
# subdivide it (slowest rank), the time with writing the .pvtp, the largest rank's peak memory,
# and the speed-up over 1 rank.
#   bench-mpi.sh SUBD_MPI MESH SCHEME LEVELS [RANKS...]   (default ranks: 1 2)
set -euo pipefail
subd_mpi=$1 mesh=$2 scheme=$3 levels=$4
shift 4
ranks=("${@:-1}")
[ $# -eq 0 ] && ranks=(1 2)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf '%s, %s level(s) on %s\n' "$scheme" "$levels" "$(basename "$mesh")"
printf '%-6s %14s %14s %16s %9s\n' ranks "subdivide s" "with write s" "peak MiB/rank" speed-up
base=""
for n in "${ranks[@]}"; do
  best="" line=""
  for run in 1 2 3; do
    summary=$(mpirun --allow-run-as-root --oversubscribe -np "$n" "$subd_mpi" "$mesh" --scheme "$scheme" \
      --levels "$levels" --output "$out/pieces.pvtp" 2>/dev/null)
    t=$(sed -n 's/.*piece and subdivision \([0-9.]*\) s.*/\1/p' <<<"$summary")
    if [ -z "$best" ] || awk "BEGIN{exit !($t < $best)}"; then best=$t line=$summary; fi
  done
  write=$(sed -n 's/.*with writing \([0-9.]*\) s.*/\1/p' <<<"$line")
  peak=$(sed -n 's/.*peak memory \([0-9.]*\) MiB.*/\1/p' <<<"$line")
  [ -z "$base" ] && base=$best
  printf '%-6s %14s %14s %16s %9.2f\n' "$n" "$best" "$write" "$peak" "$(awk "BEGIN{print $base / $best}")"
done
