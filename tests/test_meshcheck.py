from meceng.tools.meshcheck import check_mesh_size

PROGRAM = "from netgen.occ import *\nmesh = OCCGeometry(shape).GenerateMesh(maxh={maxh})\n"


def test_literal_maxh_is_kept_or_raised_silently() -> None:
    kept = check_mesh_size(PROGRAM.format(maxh="0.02"), minimum=0.005)
    assert kept.error is None and kept.maxh == (0.02,) and not kept.raised and kept.code == PROGRAM.format(maxh="0.02")
    raised = check_mesh_size(PROGRAM.format(maxh="0.0001"), minimum=0.005)
    assert raised.raised and "maxh=0.005)" in raised.code and raised.maxh == (0.0001,)


def test_missing_or_computed_maxh_is_flagged() -> None:
    assert "no hard-coded maxh" in check_mesh_size(PROGRAM.format(maxh="L / 50"), 0.005).error
    assert "no hard-coded maxh" in check_mesh_size("m = geo.GenerateMesh()\n", 0.005).error
    assert "not meshed" in check_mesh_size("x = 1\n", 0.005).error
    assert check_mesh_size(PROGRAM.format(maxh="-1"), 0.005).code is None
