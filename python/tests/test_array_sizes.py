"""Absurd array sizes (python/src/arrays.hpp): a broadcast view of 2^36 elements (np.broadcast_to of
one number: no memory) needs a float64 copy of 512 GiB; the module raises numpy's MemoryError
naming the size, never pybind11's "error_already_set called while Python error indicator not set"."""
import numpy as np
import pytest

import asperity

HUGE = 2 ** 36


@pytest.fixture(scope="module")
def curve():
    return asperity.Table.open_default().curve("gaussian")


@pytest.mark.parametrize("dtype", [np.float64, np.float32, np.int32, np.bool_])
def test_a_broadcast_of_2_36_elements_is_a_memory_error(curve, dtype):
    huge = np.broadcast_to(np.array([1], dtype=dtype), (HUGE,))
    scales = asperity.SurfaceScales()
    calls = [lambda: curve.value(0, huge), lambda: curve.log_value(3, huge),
             lambda: asperity.standardized_from_origin(curve, huge), lambda: asperity.separation_at_load(curve, huge),
             lambda: asperity.contact_at(curve, scales, huge)]
    for call in calls:
        with pytest.raises(MemoryError, match=str(HUGE)) as raised:
            call()
        assert "error_already_set" not in str(raised.value)


def test_a_two_dimensional_broadcast_too(curve):
    huge = np.broadcast_to(np.array([[0.5]]), (2 ** 18, 2 ** 18))
    with pytest.raises(MemoryError, match=str(2 ** 18)):
        curve.value(0, huge)
    small = np.broadcast_to(np.array([0.5]), (7,))  # a broadcast that fits is answered
    assert np.array_equal(curve.value(0, small), np.full(7, curve.value(0, 0.5)))
