# slurm-cluster.sh: starts and stops a private single-node SLURM (munged, slurmctld, slurmd) whose
# configuration, sockets, ports and state all live under one directory, so it touches nothing of
# the machine's own. Sourced by the farm tests. Needs root (slurmd runs jobs as their user).
#   slurm_start DIR   start the daemons; exports SLURM_CONF
#   slurm_stop        stop exactly the daemons slurm_start started, by their process ids
slurm_free_port() {
	# A port from a range away from SLURM's defaults (6817-6819), chosen by our pid.
	echo $(( 20000 + ($$ * 7 + $1) % 20000 ))
}

slurm_start() {
	SLURM_DIR=$1
	mkdir -p "$SLURM_DIR/state" "$SLURM_DIR/spool" "$SLURM_DIR/munge" "$SLURM_DIR/log" || return 1
	chmod 700 "$SLURM_DIR/munge"
	dd if=/dev/urandom of="$SLURM_DIR/munge/munge.key" bs=1024 count=1 2>/dev/null || return 1
	chmod 400 "$SLURM_DIR/munge/munge.key"
	munged --force --socket="$SLURM_DIR/munge/munge.sock" --key-file="$SLURM_DIR/munge/munge.key" \
		--pid-file="$SLURM_DIR/munge/munged.pid" --log-file="$SLURM_DIR/log/munged.log" \
		--seed-file="$SLURM_DIR/munge/munge.seed" || return 1
	host=$(hostname -s)
	cpus=$(nproc)
	ctld_port=$(slurm_free_port 1)
	slurmd_port=$(slurm_free_port 2)
	cat >"$SLURM_DIR/slurm.conf" <<EOC
ClusterName=circetest
SlurmctldHost=$host
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$SLURM_DIR/munge/munge.sock
CredType=cred/munge
StateSaveLocation=$SLURM_DIR/state
SlurmdSpoolDir=$SLURM_DIR/spool
SlurmctldPidFile=$SLURM_DIR/slurmctld.pid
SlurmdPidFile=$SLURM_DIR/slurmd.pid
SlurmctldLogFile=$SLURM_DIR/log/slurmctld.log
SlurmdLogFile=$SLURM_DIR/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
SlurmctldTimeout=30
SlurmdTimeout=30
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=circe Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOC
	export SLURM_CONF="$SLURM_DIR/slurm.conf"
	slurmctld -f "$SLURM_CONF" -i || return 1
	slurmd -f "$SLURM_CONF" || return 1
	# Wait until the node is idle (up to 60 s).
	for _ in $(seq 60); do
		state=$(sinfo -h -N -o '%t' 2>/dev/null | head -n 1)
		[ "$state" = idle ] && return 0
		sleep 1
	done
	echo "slurm_start: the node never became idle (state '$state')" >&2
	return 1
}

slurm_stop() {
	[ -n "$SLURM_DIR" ] || return 0
	for f in slurmd.pid slurmctld.pid munge/munged.pid; do
		if [ -f "$SLURM_DIR/$f" ]; then
			pid=$(cat "$SLURM_DIR/$f")
			kill "$pid" 2>/dev/null
			for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
			kill -9 "$pid" 2>/dev/null
		fi
	done
	return 0
}
