"""demo/gimbal_lock.py, bounded: it runs through the first gimbal lock (t = 1 s), writes its plot
and reports an attitude error at the method's level."""
import pytest

from attitude_support import ATTITUDE_FMU_PATH
from demo import gimbal_lock


@pytest.mark.slow
def test_gimbal_lock_demo_runs_and_writes_its_plot(tmp_path):
    output = tmp_path / "gimbal_lock.png"
    worst = gimbal_lock.main(["--fmu", str(ATTITUDE_FMU_PATH), "--stop-time", "1.5",
                              "--step", "1e-3", "--output", str(output)])
    assert output.is_file() and output.stat().st_size > 10000
    assert worst < 1e-9  # the attitude itself never notices the singular angles
