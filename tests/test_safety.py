import pytest

from meceng.tools.safety import check_program

OK = "import exudyn as exu\nfrom exudyn.utilities import *\nimport numpy as np\nimport math\nx = np.sin(1)\n"


def test_plain_exudyn_program_passes() -> None:
    assert check_program(OK)


@pytest.mark.parametrize(
    ("source", "reason"),
    [
        ("import os\nos.remove('x')", "import of module 'os'"),
        ("import subprocess", "import of module 'subprocess'"),
        ("from shutil import rmtree", "import from module 'shutil'"),
        ("import socket", "import of module 'socket'"),
        ("f = open('/etc/passwd')", "use of 'open'"),
        ("exec('import os')", "use of 'exec'"),
        ("__import__('os')", "use of '__import__'"),
        ("getattr(__builtins__, 'open')", "use of 'getattr'"),
        ("x = ().__class__.__bases__[0].__subclasses__()", "interpreter internals"),
        ("import numpy as np\nnp.savetxt('a.txt', [1])", "'.savetxt'"),
        ("import matplotlib.pyplot as plt\nplt.savefig('a.png')", "'.savefig'"),
        ("def f(:\n  pass", "syntax error"),
    ],
)
def test_hostile_or_file_writing_programs_are_refused(source: str, reason: str) -> None:
    verdict = check_program(source)
    assert not verdict and reason in verdict.reason
