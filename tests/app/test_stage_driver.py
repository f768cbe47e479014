"""The stage's driver formulas (protocol/stage/driver.py) and LED ring (protocol/stage/led.py).

The numbers are worked out by hand from the original's equations: IRMS =
(CS+1)/32 · VFS/(Rsense+20 mΩ) · 1/√2 with VFS 0.32 V and Rsense 0.11 Ω, and
fSTEP = 80 MHz / ((PSC+1)(ARR+1)) with a 16-bit timer.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from protocol.stage.codec import DeviceFlag
from protocol.stage.driver import (
    StepTimer,
    format_current,
    quantised_speed,
    rms_current_a,
    step_timer,
)
from protocol.stage.led import LedRing, led_ring


def test_s3_18_rms_current_follows_equation_7_1() -> None:
    # 0.32 V / 0.13 Ω = 2.4615 A peak at full scale; / √2 = 1.7406 A rms.
    full = 0.32 / 0.13 / math.sqrt(2)
    assert rms_current_a(31) == pytest.approx(full)
    assert rms_current_a(31) == pytest.approx(1.7406, abs=1e-4)
    assert rms_current_a(16) == pytest.approx(17 / 32 * full)  # 0.9247 A
    assert rms_current_a(0) == pytest.approx(full / 32)  # 54 mA
    # Another board: VSENSE = 1 (0.18 V) with 0.22 Ω.
    assert rms_current_a(31, vfs_v=0.18, rsense_ohm=0.22) == pytest.approx(0.18 / 0.24 / 2**0.5)
    with pytest.raises(ValueError):
        rms_current_a(32)


def test_s3_18_currents_read_in_ma_below_an_ampere() -> None:
    assert format_current(rms_current_a(0)) == "54 mA"
    assert format_current(rms_current_a(16)) == "925 mA"
    assert format_current(rms_current_a(31)) == "1.74 A"


def test_s3_28_psc_and_arr_take_the_finest_prescaler_and_whole_ticks() -> None:
    # 10 mm/s at 0.3125 µm: 32 kHz, 2500 ticks exactly.
    assert step_timer(32_000) == StepTimer(0, 2499)
    # 3.2 Hz: 25 000 000 ticks do not fit 16 bits; prescaler 382, 65445.03 → 65445.
    assert step_timer(3.2) == StepTimer(381, 65444)
    # 2.56 MHz: 31.25 ticks, truncated to 31, so the real rate is a little faster.
    timer = step_timer(2_560_000)
    assert timer == StepTimer(0, 30)
    assert timer.rate_hz == pytest.approx(2_580_645.16, abs=0.01)
    # Beyond the timer's reach: its fastest and slowest periods.
    assert step_timer(1e9) == StepTimer(0, 1)
    assert step_timer(1e-4) == StepTimer(65535, 65535)


def test_s3_28_quantised_speeds() -> None:
    micro = 1000 / (200 * 256)
    assert quantised_speed(50_000, micro) == pytest.approx(50_403.2258, abs=1e-3)
    assert quantised_speed(10_000, 0.3125) == 10_000  # an exact period
    assert quantised_speed(0, 0.3125) == 0
    # Whatever the speed, the timer runs at least as fast as asked, short by less than one
    # prescaled tick of the period.
    for speed in (1, 7, 333, 2_000, 12_345, 99_999, 999_999):
        real = quantised_speed(speed, 0.3125)
        ticks = 80e6 / (speed / 0.3125)
        tick = math.ceil(ticks / 65536)
        assert speed <= real < speed * ticks / (ticks - tick)


def test_s3_33_the_led_ring_follows_the_device_flags_in_table_order() -> None:
    assert led_ring(0) is LedRing.PAIRING
    assert led_ring(DeviceFlag.DATA_SESSION) is LedRing.TALKING
    assert led_ring(DeviceFlag.DATA_SESSION | DeviceFlag.SLEEPING) is LedRing.STANDBY
    assert led_ring(DeviceFlag.SLEEPING | DeviceFlag.LOW_BATTERY) is LedRing.LOW_BATTERY
    assert led_ring(DeviceFlag.LOW_BATTERY | DeviceFlag.CHARGER) is LedRing.CHARGING
    assert led_ring(DeviceFlag.USB | DeviceFlag.DATA_SESSION) is LedRing.TALKING


def test_s3_18_the_profile_names_the_drivers_vfs_and_rsense(tmp_path: Path) -> None:
    from app.profiles import MACHINES_DIR, DriverSettings, ProfileError, load_profile

    stage = load_profile("xy-stage").driver
    assert (stage.vfs_v, stage.rsense_ohm, stage.step_clock_hz) == (0.32, 0.11, 80_000_000)
    text = (MACHINES_DIR / "xy-stage.toml").read_text(encoding="utf-8")
    other = tmp_path / "other.toml"
    other.write_text(text.replace("vfs_v = 0.32", "vfs_v = 0.18"), encoding="utf-8")
    assert load_profile(other).driver.vfs_v == 0.18
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace("vfs_v = 0.32", "vfs_v = 0"), encoding="utf-8")
    with pytest.raises(ProfileError, match=r"\[driver\]"):
        load_profile(bad)
    assert load_profile("usb3").driver == DriverSettings()  # no [driver]: the defaults
