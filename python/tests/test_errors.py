"""Every library error variant reaches Python with its own name and the class of its kind.

The examples are made in Rust (one of each variant, checked there against the enum's declaration)
and turned into exceptions by the same code as any error.
"""

from __future__ import annotations

import halfplane
from halfplane import _halfplane, errors

CLASS_OF_KIND = {
    "input": (errors.InputError, ValueError),
    "outside-analysis": (errors.OutsideAnalysisError, ValueError),
    "solver": (errors.SolverError, RuntimeError),
}


def test_every_variant_has_its_own_name_and_the_class_of_its_kind() -> None:
    examples = _halfplane._error_examples()
    names = [name for name, _, _ in examples]
    assert len(names) >= 30
    assert len(set(names)) == len(names), "names are unique"
    assert "Other" not in names
    for name, kind, exception in examples:
        cls, builtin = CLASS_OF_KIND[kind]
        assert type(exception) is cls, (name, kind, type(exception))
        assert isinstance(exception, halfplane.HalfplaneError)
        assert isinstance(exception, builtin)
        assert exception.variant == name
        assert str(exception)


def test_matching_errors_are_not_input_errors() -> None:
    kinds = {name: kind for name, kind, _ in _halfplane._error_examples()}
    assert kinds["NoValidMatch"] == "outside-analysis"
    assert kinds["MatchNotBracketed"] == "outside-analysis"
    for name in ["MomentOutsideTable", "OutsideProfile", "InvalidRange", "UnequalColumns",
                 "LengthMismatch", "MissingConstants"]:
        assert kinds[name] == "input", name


def test_cycles_the_march_covers_point_to_it() -> None:
    # The example NoConvergence is the stick-zone equations' (no root), which the march may get
    # past; the other non-convergences carry no pointer (checked in the library's tests).
    hinted = {
        name
        for name, _, exception in _halfplane._error_examples()
        if "halfplane.march" in str(exception)
    }
    assert hinted == {"SlipReversesInHalf", "StickZoneOutsideContact", "NoConvergence"}
