#!/usr/bin/env bash
# A one-node Slurm cluster on this machine with every file in DIR: the munge
# key, socket and logs, slurm.conf, the controller's state, slurmd's spool,
# pid files and logs. Nothing is written to /etc, /run, /var or /dev, and the
# daemons are stopped by the pids recorded at start.
#
#   local-slurm.sh start DIR   start munged, slurmctld and slurmd; wait until the node is idle
#   local-slurm.sh stop DIR    cancel the cluster's jobs, stop the daemons (by pid)
#
# LOCAL_SLURM_EXTRA_CONF, if set, is appended to slurm.conf (e.g. MaxArraySize=5).
# Then: export SLURM_CONF=DIR/slurm.conf (sbatch, squeue, ... find the cluster
# through it). Needs Debian's slurm-wlm and munge (scripts/install-deps.sh).
# Each Debian default path is overridden here: slurm.conf (SLURM_CONF), the
# controller's and slurmd's pid files (/run), StateSaveLocation
# (/var/lib/slurm/slurmctld), SlurmdSpoolDir (/var/lib/slurm/slurmd), the logs
# (syslog), PlugStackConfig (/etc/slurm/plugstack.conf), and munged's key,
# socket, pid, seed and log files (/etc/munge, /run/munge, /var/lib/munge,
# /var/log/munge).
set -euo pipefail

die() { echo "local-slurm: $*" >&2; exit 1; }

free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# Waits up to $2 seconds for command $1 to succeed.
wait_for() {
    local check=$1 seconds=$2 i
    for ((i = 0; i < seconds * 5; i++)); do
        if eval "$check" >/dev/null 2>&1; then return 0; fi
        sleep 0.2
    done
    return 1
}

start() {
    local dir=$1
    for tool in munged slurmctld slurmd sbatch; do
        command -v "$tool" >/dev/null || die "$tool not found; install Debian's slurm-wlm and munge (scripts/install-deps.sh)"
    done
    mkdir -p "$dir"
    dir=$(cd "$dir" && pwd)
    [[ ! -e $dir/slurm.conf ]] || die "$dir already holds a cluster; stop it first"
    # munged refuses a socket that not every user can reach: each folder above it must be searchable by all.
    local up=$dir
    while [[ $up != / ]]; do
        [[ $(stat -c %A "$up") == ?????????[xt] ]] || die "$up is not searchable by all users (chmod o+x), which munged requires of its socket's folders"
        up=$(dirname "$up")
    done
    mkdir -p "$dir"/{munge,state,spool,log}
    # munged insists: the socket's folder searchable by all, the key readable by its owner only.
    chmod 755 "$dir" "$dir/munge"
    head -c 1024 /dev/urandom >"$dir/munge/munge.key"
    chmod 400 "$dir/munge/munge.key"
    munged --foreground --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
        --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed" \
        </dev/null >>"$dir/log/munged.out" 2>&1 &
    echo $! >"$dir/munged.pid"
    wait_for "[[ -S '$dir/munge/munge.socket' ]]" 20 || die "munged did not start; see $dir/munge/munged.log"

    local host node_line node
    host=$(hostname -s)
    # The node exactly as slurmd sees this machine (CPUs, sockets, memory), so it registers as valid.
    node_line=$(slurmd -C | head -n 1)
    [[ $node_line == NodeName=* ]] || die "slurmd -C did not describe this machine: $node_line"
    node=${node_line#NodeName=}
    node=${node%% *}
    touch "$dir/plugstack.conf"
    cat >"$dir/slurm.conf" <<CONF
# Written by tests/farm/local-slurm.sh: a one-node cluster, all of it in $dir.
ClusterName=orblocal
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
SlurmUser=$(id -un)
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid.slurm
SlurmdPidFile=$dir/slurmd.pid.slurm
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
PlugStackConfig=$dir/plugstack.conf
# No cgroups: processes are tracked through /proc and tasks are not bound.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MailProg=/bin/true
ReturnToService=2
${node_line} NodeHostname=$host NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
${LOCAL_SLURM_EXTRA_CONF-}
CONF

    export SLURM_CONF=$dir/slurm.conf
    slurmctld -D -f "$SLURM_CONF" </dev/null >>"$dir/log/slurmctld.out" 2>&1 &
    echo $! >"$dir/slurmctld.pid"
    slurmd -D -f "$SLURM_CONF" -N "$node" </dev/null >>"$dir/log/slurmd.out" 2>&1 &
    echo $! >"$dir/slurmd.pid"
    if ! wait_for "[[ \$(sinfo -h -o %T 2>/dev/null) == idle ]]" 60; then
        tail -n 20 "$dir/log/slurmctld.log" "$dir/log/slurmd.log" >&2 || true
        die "the node did not come up within 60 s (logs above, in $dir/log)"
    fi
    echo "local-slurm: cluster up: export SLURM_CONF=$SLURM_CONF"
}

stop_pid() {
    local file=$1 pid i
    [[ -f $file ]] || return 0
    pid=$(<"$file")
    if kill "$pid" 2>/dev/null; then
        for ((i = 0; i < 50; i++)); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.2
        done
        kill -KILL "$pid" 2>/dev/null || true
    fi
    wait "$pid" 2>/dev/null || true
    rm -f "$file"
}

stop() {
    local dir=$1
    [[ -d $dir ]] || return 0
    dir=$(cd "$dir" && pwd)
    if [[ -f $dir/slurm.conf && -f $dir/slurmctld.pid ]]; then
        # Jobs first, so that no job step outlives slurmd.
        export SLURM_CONF=$dir/slurm.conf
        if scancel --user="$(id -un)" 2>/dev/null; then
            wait_for "[[ -z \$(squeue -h 2>/dev/null) ]]" 20 || echo "local-slurm: jobs still listed after scancel" >&2
        fi
    fi
    stop_pid "$dir/slurmd.pid"
    stop_pid "$dir/slurmctld.pid"
    stop_pid "$dir/munged.pid"
}

case ${1-} in
start) [[ $# == 2 ]] || die "usage: local-slurm.sh start DIR"; start "$2" ;;
stop) [[ $# == 2 ]] || die "usage: local-slurm.sh stop DIR"; stop "$2" ;;
*) die "usage: local-slurm.sh start|stop DIR" ;;
esac
