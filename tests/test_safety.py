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
        ("import numpy as np\nx = np.load('/work/runs/r/traces/a.npz')", "'.load' is not allowed (reads files)"),
        ("import numpy\nx = numpy.loadtxt('ref.txt')", "'.loadtxt'"),
        ("from numpy import load\nload('a.npy')", "import of 'load'"),
        ("import scipy.io\nscipy.io.loadmat('a.mat')", "'.loadmat'"),
        ("import exudyn as exu\nexu.SetWriteToFile('/home/x/log.txt')", "'.SetWriteToFile'"),
        ("x = (1).__class__", "interpreter internals '__class__'"),
        ("def f(): pass\ng = f.__globals__", "interpreter internals '__globals__'"),
        ("def f(:\n  pass", "syntax error"),
    ],
)
def test_programs_the_runtime_guard_cannot_contain_are_refused(source: str, reason: str) -> None:
    verdict = check_program(source)
    assert not verdict and reason in verdict.reason


@pytest.mark.parametrize(
    "source",
    [
        "values = [1, 2, 3]\nvalues.remove(2)",
        "class Store:\n    def load(self):\n        return 1\n    def save(self):\n        return 2\n"
        "s = Store()\ns.load()\ns.save()",
        "import exudyn as exu\nprint(exu.__version__)",
        "import matplotlib.pyplot as plt\nplt.plot([0, 1])\nplt.savefig('a.png')",
        "import numpy as np\nnp.savetxt('a.txt', [1])",
        "d = {'a': 1}\nd.pop('a')\nd.update(b=2)\nprint(__name__)",
        "class Body:\n    def __init__(self):\n        super().__init__()\nprint(Body.__name__, Body.__doc__)",
        "if __name__ == '__main__':\n    pass",
    ],
)
def test_ordinary_python_is_left_to_the_runtime_guard(source: str) -> None:
    verdict = check_program(source)
    assert verdict, verdict.reason
