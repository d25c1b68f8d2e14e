"""A one-node Slurm cluster on this machine for the tests of `hpcontact study --executor slurm`:
slurmctld and slurmd started in the foreground (their process ids are the Popen objects') with a
generated slurm.conf (no systemd, no cgroups: proctrack/linuxproc, task/none; auth/none, so no
munged), state, spool and logs in a private temporary folder, free ports, every wait bounded.
The daemons are stopped by their process ids when the session ends, whatever the tests did; a
daemon that does not start fails the tests with its log."""
import pwd
import os
import shutil
import socket
import subprocess
import sys
import time

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.append(os.path.join(ROOT, "tests"))
from timeouts import scaled_timeout  # noqa: E402  (the time limits, also the test files')
# Bounds of the waits on a quiet machine (scaled_timeout stretches them on a busy one).
START_SECONDS = 60     # the node must be idle within this
STOP_SECONDS = 20      # a daemon must end within this of SIGTERM (then SIGKILL)
COMMAND_SECONDS = 30   # any one client command


def pytest_addoption(parser):
    parser.addoption("--hpcontact", default=os.path.join(ROOT, "build", "hpcontact"),
                     help="path of the hpcontact executable")


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def slurm_conf(folder, node, user, ctld_port, slurmd_port):
    # slurmctld runs only on the host SlurmctldHost names: this one (its short name).
    host = socket.gethostname().split(".")[0]
    return f"""# A private one-node cluster of the hpcontact tests (tests/slurm/conftest.py).
ClusterName=hpctest
SlurmctldHost={host}(127.0.0.1)
SlurmctldPort={ctld_port}
SlurmdPort={slurmd_port}
AuthType=auth/none
CredType=cred/none
SlurmUser={user}
SlurmdUser={user}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
MinJobAge=600
SlurmctldTimeout=30
SlurmdTimeout=30
StateSaveLocation={folder}/state
SlurmdSpoolDir={folder}/spool
SlurmctldPidFile={folder}/slurmctld.pid
SlurmdPidFile={folder}/slurmd.pid
SlurmctldLogFile={folder}/log/slurmctld.log
SlurmdLogFile={folder}/log/slurmd.log
NodeName={node} NodeAddr=127.0.0.1 CPUs=2 RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes={node} Default=YES MaxTime=INFINITE State=UP
"""


class Cluster:
    """The running cluster: `env` for every command that talks to it, `run` for client commands."""

    def __init__(self, folder):
        self.folder = folder
        self.node = "hpcnode"
        self.conf = os.path.join(folder, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)
        self.daemons = {}

    def log(self, name):
        path = os.path.join(self.folder, "log", name + ".log")
        if not os.path.exists(path):
            return f"({path} was not written)"
        with open(path, encoding="utf-8", errors="replace") as f:
            return f.read()[-6000:]

    def logs(self):
        return "\n".join(f"--- {name}.log ---\n{self.log(name)}\n--- its output ---\n{self.output(name)}"
                         for name in self.daemons)

    def output(self, name):
        path = os.path.join(self.folder, "log", name + ".out")
        with open(path, encoding="utf-8", errors="replace") as f:
            return f.read()[-3000:]

    def run(self, *args, check=True):
        r = subprocess.run(list(args), env=self.env, capture_output=True, text=True,
                           timeout=scaled_timeout(COMMAND_SECONDS))
        if check and r.returncode != 0:
            raise AssertionError(f"{' '.join(args)}: exit {r.returncode}: {r.stderr}\n{self.logs()}")
        return r

    def start(self, name, argv):
        with open(os.path.join(self.folder, "log", name + ".out"), "w") as out:
            self.daemons[name] = subprocess.Popen(argv, env=self.env, stdout=out,
                                                  stderr=subprocess.STDOUT,
                                                  stdin=subprocess.DEVNULL)

    def wait_idle(self):
        seconds = scaled_timeout(START_SECONDS)
        deadline = time.monotonic() + seconds
        state = ""
        while time.monotonic() < deadline:
            for name, p in self.daemons.items():
                if p.poll() is not None:
                    pytest.fail(f"{name} ended at start (exit {p.returncode}):\n{self.logs()}")
            r = self.run("sinfo", "-h", "-n", self.node, "-o", "%T", check=False)
            state = r.stdout.strip()
            if r.returncode == 0 and state == "idle":
                return
            time.sleep(0.5)
        pytest.fail(f"the node is not idle {seconds:.0f} s after the start (sinfo: '{state}'):\n"
                    f"{self.logs()}")

    def cancel_all(self):
        """Cancels every job of the cluster and waits (bounded) for the queue to empty."""
        self.run("scancel", "--full", "--user", pwd.getpwuid(os.getuid()).pw_name, check=False)
        deadline = time.monotonic() + scaled_timeout(STOP_SECONDS)
        while time.monotonic() < deadline:
            r = self.run("squeue", "-h", "-o", "%i", check=False)
            if r.returncode != 0 or not r.stdout.strip():
                return
            time.sleep(0.5)

    def stop(self):
        for name in ("slurmd", "slurmctld"):
            p = self.daemons.get(name)
            if p is None or p.poll() is not None:
                continue
            p.terminate()  # by its process id
            try:
                p.wait(timeout=scaled_timeout(STOP_SECONDS))
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait(timeout=scaled_timeout(STOP_SECONDS))


def require_slurm():
    for tool in ("slurmctld", "slurmd", "sbatch", "scontrol", "sinfo", "squeue", "scancel"):
        if not shutil.which(tool):
            pytest.fail(f"{tool} is not on PATH: scripts/install-deps.sh installs slurmctld, slurmd "
                        "and slurm-client (Debian's slurm-wlm)")


def boot(folder, extra_conf=""):
    """A cluster in `folder`, configured, not started; `extra_conf` lines are appended to
    slurm.conf."""
    for sub in ("state", "spool", "log"):
        os.makedirs(os.path.join(folder, sub), exist_ok=True)
    c = Cluster(folder)
    with open(c.conf, "w") as f:
        f.write(slurm_conf(folder, c.node, pwd.getpwuid(os.getuid()).pw_name, free_port(), free_port()) + extra_conf)
    return c


def start(c):
    """Starts the daemons; fails the test (with their logs) if the node is not idle in time. The
    caller stops them (Cluster.stop), also when this fails."""
    c.start("slurmctld", ["slurmctld", "-D", "-i", "-f", c.conf])
    c.start("slurmd", ["slurmd", "-D", "-f", c.conf, "-N", c.node])
    c.wait_idle()


@pytest.fixture(scope="session")
def cluster(tmp_path_factory):
    require_slurm()
    c = boot(str(tmp_path_factory.mktemp("slurm")))
    try:
        start(c)
        yield c
    finally:
        try:
            c.cancel_all()
        finally:
            c.stop()


@pytest.fixture(scope="session")
def exe(request):
    path = os.path.abspath(request.config.getoption("--hpcontact"))
    if not os.path.exists(path):
        pytest.fail(f"hpcontact executable not found at {path}")
    return path
