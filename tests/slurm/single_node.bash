# shellcheck shell=bash
# single_node.bash - a one-node Slurm (slurmctld, slurmd, munged) living in one folder, for the
# tests (sourced). Everything it writes (configuration, key, state, spool, logs, pid files,
# sockets) stays in that folder, and slurm_stop ends the daemons by their pids. Start it in a
# private network namespace (unshare --net, with lo up): its only address is then 127.0.0.1,
# so the daemons, which bind to any address, are reachable from nowhere else. The ports are
# chosen free when it starts.
#
#   slurm_start DIR   start the daemons; sets SLURM_CONF for the client commands
#   slurm_stop        stop them (safe to call twice, and from an EXIT trap)

SLURM_DIR="" SLURM_PIDS=()

# free_ports N: N TCP ports of 127.0.0.1 free at this moment.
free_ports() {
    python3 - "$1" <<'PY'
import socket, sys
socks = [socket.socket() for _ in range(int(sys.argv[1]))]
for s in socks:
    s.bind(("127.0.0.1", 0))
print(" ".join(str(s.getsockname()[1]) for s in socks))
PY
}

slurm_write_conf() { # DIR CTLD_PORT SLURMD_PORT
    local d=$1
    cat >"$d/slurm.conf" <<CONF
ClusterName=torusrt
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$2
SlurmdPort=$3
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$d/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/filetxt
JobCompLoc=$d/log/jobcomp.txt
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
MinJobAge=600
SchedulerParameters=sched_interval=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
}

# wait_for SECONDS COMMAND...: until COMMAND succeeds; 1 if it did not within SECONDS.
wait_for() {
    local end=$((SECONDS + $1)); shift
    while [ $SECONDS -lt $end ]; do timeout 5 "$@" >/dev/null 2>&1 && return 0; sleep 0.2; done
    return 1
}

slurm_start() {
    local d=$1 ports
    SLURM_DIR=$d
    mkdir -p "$d/munge" "$d/state" "$d/spool" "$d/log"
    chmod 700 "$d/munge"
    dd if=/dev/urandom of="$d/munge/munge.key" bs=1024 count=1 status=none
    chmod 400 "$d/munge/munge.key"
    munged --force --socket="$d/munge/munge.socket" --key-file="$d/munge/munge.key" \
        --pid-file="$d/munge/munged.pid" --log-file="$d/log/munged.log" --seed-file="$d/munge/seed" </dev/null >/dev/null 2>&1 ||
        { echo "munged did not start: $(tail -n 3 "$d/log/munged.log")" >&2; return 1; }
    wait_for 10 test -s "$d/munge/munged.pid" && SLURM_PIDS+=("$(cat "$d/munge/munged.pid")")
    read -r -a ports < <(free_ports 2)
    slurm_write_conf "$d" "${ports[0]}" "${ports[1]}"
    export SLURM_CONF=$d/slurm.conf
    slurmctld -f "$SLURM_CONF" -i </dev/null >/dev/null 2>&1 ||
        { echo "slurmctld did not start: $(tail -n 5 "$d/log/slurmctld.log")" >&2; return 1; }
    wait_for 10 test -s "$d/slurmctld.pid" && SLURM_PIDS+=("$(cat "$d/slurmctld.pid")")
    slurmd -f "$SLURM_CONF" -N localhost </dev/null >/dev/null 2>&1 ||
        { echo "slurmd did not start: $(tail -n 5 "$d/log/slurmd.log")" >&2; return 1; }
    wait_for 10 test -s "$d/slurmd.pid" && SLURM_PIDS+=("$(cat "$d/slurmd.pid")")
    wait_for 30 sh -c 'sinfo -h -N -o %T | grep -Eq "^(idle|mixed|allocated)"' ||
        { echo "the node never became idle: $(sinfo -N 2>&1; tail -n 5 "$d/log/slurmctld.log")" >&2; return 1; }
}

slurm_stop() {
    local pid
    for pid in "${SLURM_PIDS[@]}"; do kill "$pid" 2>/dev/null; done
    for pid in "${SLURM_PIDS[@]}"; do
        for ((i = 0; i < 50; i++)); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$pid" 2>/dev/null
    done
    SLURM_PIDS=()
}
