#!/usr/bin/env bash
# A single-node Slurm on localhost for the wedge test (cli.TestCliWedge): munge, slurmctld
# and slurmd, each with its files, sockets and logs in DIR and its own ports, so it touches
# nothing of the machine's and two can run side by side. Needs root (slurmd runs jobs as
# their users) and Debian's slurmctld, slurmd, slurm-client and munge (scripts/deps.sh test).
#
#   local-slurm.sh start DIR PORT   prints DIR/slurm.conf once the node is idle (export it as
#                                   SLURM_CONF); exit 1, with the logs, when it is not up in 30 s
#   local-slurm.sh stop DIR         stops the three
set -euo pipefail

cmd=${1:?start or stop}
dir=${2:?the folder}
case $cmd in
start)
  port=${3:?a port: slurmctld's, and slurmd's the next}
  for tool in munged slurmctld slurmd sinfo sbatch; do
    command -v "$tool" >/dev/null || { echo "local-slurm: $tool is not installed (scripts/deps.sh test)" >&2; exit 1; }
  done
  mkdir -p "$dir/state" "$dir/spool"
  head -c 1024 /dev/urandom > "$dir/munge.key"
  chmod 600 "$dir/munge.key"
  munged --force --socket="$dir/munge.socket" --key-file="$dir/munge.key" --log-file="$dir/munged.log" \
    --pid-file="$dir/munged.pid" --seed-file="$dir/munged.seed"
  cat > "$dir/slurm.conf" <<CONF
ClusterName=throngtest
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
NodeName=localhost NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=throng Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$dir/slurm.conf
  slurmctld -f "$SLURM_CONF"
  slurmd -f "$SLURM_CONF" -N localhost
  for _ in $(seq 60); do
    if [ "$(sinfo -h -o %T 2>/dev/null || true)" = idle ]; then
      echo "$SLURM_CONF"
      exit 0
    fi
    sleep 0.5
  done
  echo "local-slurm: the node in $dir did not come up in 30 s" >&2
  tail -n 20 "$dir"/*.log >&2 || true
  exit 1
  ;;
stop)
  for daemon in slurmd slurmctld; do
    [ -f "$dir/$daemon.pid" ] && kill "$(cat "$dir/$daemon.pid")" 2>/dev/null || true
  done
  munged --stop --socket="$dir/munge.socket" >/dev/null 2>&1 || true
  ;;
*)
  echo "local-slurm: start DIR PORT, or stop DIR" >&2
  exit 2
  ;;
esac
