#!/usr/bin/env bash
# The test cluster from a deep checkout (issue 41): cluster.sh, copied into a folder whose path is
# about 200 characters long as a clone's would be, starts its cluster there (its cluster folder
# deeper still), runs a batch job with a job step through it, and its stop removes the private
# folder that holds the sockets. Before, munged refused a socket path over 108 bytes and slurmd
# could not create its step sockets. Everything here is removed on exit, also when a step fails.
#
#   tests/slurm/long_path_test.sh SOURCE_DIR
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 SOURCE_DIR" >&2; exit 2; }
source_dir=$1

scratch=$(mktemp -d /tmp/trapdem-slurm-longpath.XXXXXX)
checkout=$scratch
while [ ${#checkout} -lt 200 ]; do checkout="$checkout/a-rather-long-folder-name"; done
mkdir -p "$checkout/tests/slurm"
cp "$source_dir/tests/slurm/cluster.sh" "$checkout/tests/slurm/cluster.sh"
cluster="$checkout/build/tests/slurm/cluster"
script="$checkout/tests/slurm/cluster.sh"
cleanup() {
  bash "$script" stop "$cluster" || true
  rm -rf "$scratch"
}
trap cleanup EXIT
echo "checkout path: ${#checkout} characters"

bash "$script" start "$cluster"
private=$(cat "$cluster/private")
[ -d "$private" ] || { echo "FAIL: the cluster's private folder '$private' does not exist" >&2; exit 1; }

export SLURM_CONF="$cluster/slurm.conf"
out="$checkout/job.out"
timeout 120 sbatch --wait -N1 -n1 -t 1 -o "$out" --wrap 'srun -n1 echo step-ran-on-$(hostname -s)' \
  || { echo "FAIL: the job did not complete; node: $(sinfo -h -o '%t %E')" >&2; exit 1; }
grep -q "step-ran-on-" "$out" || { echo "FAIL: the job's output lacks its step's line:" >&2; cat "$out" >&2; exit 1; }

bash "$script" stop "$cluster"
[ ! -e "$private" ] || { echo "FAIL: stop left the private folder $private" >&2; exit 1; }
[ ! -e "$cluster/private" ] || { echo "FAIL: stop left $cluster/private" >&2; exit 1; }
echo "PASS: a job step ran through a cluster started from a ${#checkout}-character checkout path"
