"""A corpus of hostile programs: each ends with a recorded verdict and a clear reason, the run goes
on, a canary file outside the scratch directory stays untouched, and no process is left behind.

The programs run with the static check switched off, so the runtime layers (audit hook, process
group, limits, network namespace, result token) are what is tested; the static check's own
refusals are tested in test_safety.py.
"""

from __future__ import annotations

import os
import socket
from pathlib import Path

import pytest

from meceng.tools.execution import ExecutionLimits
from meceng.tools.executor import child_env, execute
from meceng.tools.warm import WarmPool

MODEL = """
import exudyn as exu
from exudyn.utilities import *
SC = exu.SystemContainer()
mbs = SC.AddSystem()
mbs.CreateMassPoint(referencePosition=[0, 0, 0], mass=1, gravity=[0, 0, -9.81])
mbs.Assemble()
"""
SIM = ("simulationSettings = exu.SimulationSettings()\nsimulationSettings.timeIntegration.endTime = 0.1\n"
       "simulationSettings.timeIntegration.numberOfSteps = 100\nsimulationSettings.solution.file.write = False\n"
       "mbs.SolveDynamic(simulationSettings)\n")

# name -> (program with {canary} / {port} placeholders, expected text in error or warnings)
CORPUS: dict[str, tuple[str, str]] = {
    "endless_loop": ("while True:\n    pass\n", "timeout"),
    "ignores_sigterm": ("import signal\nsignal.signal(signal.SIGTERM, signal.SIG_IGN)\nwhile True:\n    pass\n",
                        "timeout"),
    "fork_bomb": ("import os\nfor _ in range(50):\n    os.fork()\n", "sandbox refused: os.fork"),
    "memory_bomb": ("x = bytearray(64 * 1024**3)\n", "MemoryError"),
    "segfault_ctypes": ("import ctypes\nctypes.string_at(0)\n", "sandbox refused: ctypes"),
    "os_exit_before_assemble": ("import os\nos._exit(0)\n", "without a result"),
    "sys_exit_before_assemble": ("import sys\nsys.exit(0)\n", "exit"),
    # cold: the pipe is drained until the timeout; warm: stdout is a file and hits RLIMIT_FSIZE
    "huge_stdout": ("while True:\n    print('x' * 100000)\n", "timeout|File too large"),
    "subprocess_daemon": ("import subprocess\nsubprocess.Popen(['sleep', '300'], start_new_session=True)\n",
                          "sandbox refused: subprocess.Popen"),
    "os_system": ("import os\nos.system('touch {canary}.new')\n", "sandbox refused: os.system"),
    "open_write_outside": ("open({canary!r}, 'w').write('pwned')\n", "outside the scratch directory"),
    "pathlib_write": ("import pathlib\npathlib.Path({canary!r}).write_text('pwned')\n", "outside the scratch"),
    "pathlib_unlink": ("import pathlib\npathlib.Path({canary!r}).unlink()\n", "os.remove"),
    "shutil_rmtree": ("import shutil, os\nshutil.rmtree(os.path.dirname({canary!r}))\n", "shutil.rmtree"),
    "os_remove": ("import os\nos.remove({canary!r})\n", "os.remove"),
    "obfuscated_import": ("__import__('o' + 's').remove({canary!r})\n", "os.remove"),
    "getattr_trick": ("getattr(__import__('os'), 're' + 'move')({canary!r})\n", "os.remove"),
    "exec_string": ("exec(\"import os; os.remove(\" + repr({canary!r}) + \")\")\n", "os.remove"),
    "builtins_open": ("import builtins\nbuiltins.open({canary!r}, 'a').write('x')\n", "outside the scratch"),
    "symlink_escape": ("import os\nos.symlink({canary!r}, 'link')\nopen('link', 'w').write('x')\n", "outside"),
    "chdir_escape": ("import os\nos.chdir('/')\nopen('x', 'w')\n", "sandbox refused: os.chdir"),
    "kill_parent": ("import os\nos.kill(os.getppid(), 0)\n", "sandbox refused: os.kill"),
    "open_socket": ("import socket\nsocket.create_connection(('127.0.0.1', {port}), timeout=2)\n", "sandbox refused"),
    "read_secrets": ("import os\nraise RuntimeError('secret=' + os.environ.get('MECENG_TEST_SECRET', 'absent'))\n",
                     "secret=absent"),
    "patch_assemble": ("import exudyn\nexudyn.MainSystem.Assemble = lambda self: None\n",
                       "never called mbs.Assemble"),
    "fake_result_markers": ("print('{{\"stage\": \"solved\", \"overall\": true}}')\nraise ValueError('real failure')\n",
                            "real failure"),
    "forged_result_file": ("import json, os\nopen('result.json', 'w').write(json.dumps({{'stage': 'solved'}}))\n"
                           "os._exit(0)\n", "without a result"),
    "thread_never_ends": ("import threading, time\nthreading.Thread(target=lambda: time.sleep(1000)).start()\n", ""),
}


def _leftovers(root: Path) -> list[int]:
    """Processes whose working directory lies under ``root``."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit() or int(entry.name) == os.getpid():
            continue
        try:
            cwd = os.readlink(entry / "cwd")
        except OSError:
            continue
        if cwd.startswith(str(root)):
            found.append(int(entry.name))
    return found


@pytest.fixture
def listener():
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(1)
    server.settimeout(0.1)
    yield server
    server.close()


@pytest.fixture(params=["cold", "warm"])
async def pool(request):
    """The same corpus through a cold interpreter and through the warm fork server."""
    if request.param == "cold":
        yield None
        return
    warm = WarmPool(child_env())
    await warm.start()
    yield warm
    await warm.close()


@pytest.mark.parametrize("name", sorted(CORPUS))
async def test_hostile_program_is_contained(name: str, tmp_path: Path, listener, monkeypatch, pool) -> None:
    monkeypatch.setenv("MECENG_TEST_SECRET", "hunter2")
    canary = tmp_path / "canary.txt"
    canary.write_text("original")
    scratch_root = tmp_path / "scratch"
    scratch_root.mkdir()
    body, expected = CORPUS[name]
    port = listener.getsockname()[1]
    program = body.format(canary=str(canary), port=port) + MODEL
    result = await execute(program, SIM, ExecutionLimits(timeout_s=4.0), scratch_root=scratch_root, check=False,
                           pool=pool)

    reasons = " ".join([result.error or "", *result.warnings])
    assert any(e in reasons for e in expected.split("|")), (result.stage, result.error, result.warnings)
    if name != "thread_never_ends":
        assert not result.solved
    assert canary.read_text() == "original"
    assert not Path(str(canary) + ".new").exists()
    assert _leftovers(tmp_path) == []
    assert list(scratch_root.iterdir()) == []  # scratch removed
    with pytest.raises(TimeoutError):  # nothing ever connected to the listener
        listener.accept()


async def test_sensor_files_are_not_written_anywhere(tmp_path: Path, pool) -> None:
    """Exudyn writes sensor files from C++, past the audit hook: the harness switches them off, so
    a sensor aimed outside the scratch folder writes nothing and the program still solves."""
    target = tmp_path / "outside" / "sensor.txt"
    target.parent.mkdir()
    scratch_root = tmp_path / "scratch"
    scratch_root.mkdir()
    program = MODEL.replace("mbs.Assemble()", "n = mbs.GetObject(0)['nodeNumber']\n"
                            f"mbs.AddSensor(SensorNode(nodeNumber=n, fileName={str(target)!r}, writeToFile=True,"
                            " outputVariableType=exu.OutputVariableType.Position))\nmbs.Assemble()")
    result = await execute(program, SIM, ExecutionLimits(timeout_s=20.0), scratch_root=scratch_root, pool=pool)
    assert result.solved, result.error
    assert not target.exists() and list(target.parent.iterdir()) == []
