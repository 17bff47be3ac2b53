#!/usr/bin/env bash
# A one-node Slurm cluster on this machine with every file in DIR: the munge
# key, socket and logs, slurm.conf, the controller's state, slurmd's spool,
# pid files and logs. Nothing is written to /etc, /run, /var or /dev, and the
# daemons are stopped by the pids recorded at start.
#
#   local-slurm.sh start DIR   start munged, slurmctld and slurmd; wait until the node is idle
#   local-slurm.sh stop DIR    cancel the cluster's jobs, stop the daemons (by pid)
#
# Sourced, it defines local_slurm_start DIR and local_slurm_stop DIR, so that
# the daemons are the caller's children (a test that waits for them leaves
# no zombies behind).
#
# LOCAL_SLURM_EXTRA_CONF, if set, is appended to slurm.conf (e.g. MaxArraySize=5).
# Then: export SLURM_CONF=DIR/slurm.conf (sbatch, squeue, ... find the cluster
# through it). Needs Debian's slurm-wlm and munge (scripts/install-deps.sh).
# Every default location of Debian 12's Slurm 22.05 and munge 0.5.15 (read
# from the binaries) is overridden: slurm.conf (/etc/slurm, through
# SLURM_CONF and -f), the pid files (/run/slurmctld.pid, /run/slurmd.pid),
# StateSaveLocation (/var/spool), SlurmdSpoolDir (/var/spool/slurmd), the
# logs (syslog), and munged's key, socket, pid, seed and log files
# (/etc/munge/munge.key, /run/munge, /var/lib/munge, /var/log/munge).
# PlugStackConfig points at an empty file here, although its default is
# already next to slurm.conf.

local_slurm_die() { echo "local-slurm: $*" >&2; exit 1; }

local_slurm_free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# Waits up to $2 seconds for command $1 to succeed.
local_slurm_wait_for() {
    local check=$1 seconds=$2 i
    for ((i = 0; i < seconds * 5; i++)); do
        if eval "$check" >/dev/null 2>&1; then return 0; fi
        sleep 0.2
    done
    return 1
}

local_slurm_start() {
    local dir=$1 tool
    for tool in munged slurmctld slurmd sbatch; do
        command -v "$tool" >/dev/null || local_slurm_die "$tool not found; install Debian's slurm-wlm and munge (scripts/install-deps.sh)"
    done
    mkdir -p "$dir" || local_slurm_die "cannot create $dir"
    dir=$(cd "$dir" && pwd)
    [[ ! -e $dir/slurm.conf ]] || local_slurm_die "$dir already holds a cluster; stop it first"
    # munged refuses a socket that not every user can reach: each folder above it must be searchable by all.
    local up=$dir
    while [[ $up != / ]]; do
        [[ $(stat -c %A "$up") == ?????????[xt] ]] || local_slurm_die "$up is not searchable by all users (chmod o+x), which munged requires of its socket's folders"
        up=$(dirname "$up")
    done
    # munged insists: the socket's folder searchable by all, the key readable by its owner only.
    mkdir -p "$dir"/{munge,state,spool,log} && chmod 755 "$dir" "$dir/munge" &&
        head -c 1024 /dev/urandom >"$dir/munge/munge.key" && chmod 400 "$dir/munge/munge.key" ||
        local_slurm_die "cannot set up $dir"
    munged --foreground --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
        --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed" \
        </dev/null >>"$dir/log/munged.out" 2>&1 &
    echo $! >"$dir/munged.pid"
    local_slurm_wait_for "[[ -S '$dir/munge/munge.socket' ]]" 20 || local_slurm_die "munged did not start; see $dir/munge/munged.log"

    local host node_line node
    host=$(hostname -s)
    # The node exactly as slurmd sees this machine (CPUs, sockets, memory), so it registers as valid.
    node_line=$(slurmd -C | head -n 1)
    [[ $node_line == NodeName=* ]] || local_slurm_die "slurmd -C did not describe this machine: $node_line"
    node=${node_line#NodeName=}
    node=${node%% *}
    touch "$dir/plugstack.conf" || local_slurm_die "cannot write in $dir"
    cat >"$dir/slurm.conf" <<CONF
# Written by tests/farm/local-slurm.sh: a one-node cluster, all of it in $dir.
ClusterName=orblocal
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(local_slurm_free_port)
SlurmdPort=$(local_slurm_free_port)
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
    if ! local_slurm_wait_for "[[ \$(sinfo -h -o %T 2>/dev/null) == idle ]]" 60; then
        tail -n 20 "$dir/log/slurmctld.log" "$dir/log/slurmd.log" >&2 || true
        local_slurm_die "the node did not come up within 60 s (logs above, in $dir/log)"
    fi
    echo "local-slurm: cluster up: export SLURM_CONF=$SLURM_CONF"
}

# The process with pid $1 exists, is not a zombie, and runs program $2.
local_slurm_alive() {
    [[ $({ tr '\0' ' ' </proc/"$1"/cmdline; } 2>/dev/null) == *"$2"* ]] &&
        [[ $(awk '{ print $3 }' "/proc/$1/stat" 2>/dev/null) != Z ]]
}

# Stops the daemon whose pid local_slurm_start recorded in FILE, if that pid
# still runs NAME (a stale file must not make us signal whatever has the pid now).
local_slurm_stop_pid() {
    local file=$1 name=$2 pid i
    [[ -f $file ]] || return 0
    pid=$(<"$file")
    rm -f "$file"
    [[ $pid =~ ^[0-9]+$ ]] || return 0
    if local_slurm_alive "$pid" "$name"; then
        kill "$pid" 2>/dev/null
        for ((i = 0; i < 100; i++)); do
            local_slurm_alive "$pid" "$name" || break
            sleep 0.1
        done
        if local_slurm_alive "$pid" "$name"; then
            echo "local-slurm: $name (pid $pid) did not stop within 10 s; killing it" >&2
            kill -KILL "$pid" 2>/dev/null
        fi
    fi
    # Reaps it when it is our child (local-slurm.sh sourced); otherwise init does.
    wait "$pid" 2>/dev/null || true
}

local_slurm_stop() {
    local dir=$1
    [[ -d $dir ]] || return 0
    dir=$(cd "$dir" && pwd)
    if [[ -f $dir/slurm.conf && -f $dir/slurmctld.pid ]]; then
        # Jobs first, so that no job step outlives slurmd.
        export SLURM_CONF=$dir/slurm.conf
        if scancel --user="$(id -un)" 2>/dev/null; then
            local_slurm_wait_for "[[ -z \$(squeue -h 2>/dev/null) ]]" 20 || echo "local-slurm: jobs still listed after scancel" >&2
        fi
    fi
    local_slurm_stop_pid "$dir/slurmd.pid" slurmd
    local_slurm_stop_pid "$dir/slurmctld.pid" slurmctld
    local_slurm_stop_pid "$dir/munged.pid" munged
}

if [[ ${BASH_SOURCE[0]} == "$0" ]]; then
    set -euo pipefail
    case ${1-} in
    start) [[ $# == 2 ]] || local_slurm_die "usage: local-slurm.sh start DIR"; local_slurm_start "$2" ;;
    stop) [[ $# == 2 ]] || local_slurm_die "usage: local-slurm.sh stop DIR"; local_slurm_stop "$2" ;;
    *) local_slurm_die "usage: local-slurm.sh start|stop DIR" ;;
    esac
fi
