"""The block maker's default and bounds of a number input, typed key by key, are read the way the window's
language writes numbers: "2,5" in German is 2.5; in English it is said to be no number, never taken as 25."""
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QLineEdit
from test_block_maker import open_maker


def type_into(maker, name, keys):
    edit = maker.fields.findChild(QLineEdit, name)
    edit.setFocus()
    QTest.keyClicks(edit, keys)


def made_speed_input(qtbot, window, default, minimum, maximum):
    """A drive block whose input is /cmd_vel's linear.x, its default and bounds typed in."""
    maker = open_maker(qtbot, window)
    assert maker.choose_named("/cmd_vel")
    maker.fields.set_use("linear.x", "input")
    for column, keys in (("maker_value", default), ("maker_minimum", minimum), ("maker_maximum", maximum)):
        type_into(maker, f"{column}_linear.x", keys)
    maker.sentence["en"].setText("drive at %1")
    maker.sentence["de"].setText("fahre mit %1")
    maker.block_id.setText("made_drive")
    return maker


def test_german_default_and_bounds_are_read_with_a_decimal_comma(qtbot, german_window):
    maker = made_speed_input(qtbot, german_window, "0,25", "-0,5", "1.000")
    (made,) = maker.fields.inputs()
    assert (made.default, made.minimum, made.maximum) == (0.25, -0.5, 1000)
    qtbot.waitUntil(lambda: not maker.problems, timeout=5000)


def test_english_2_comma_5_is_no_number_for_the_default_nor_a_bound(qtbot, window):
    maker = made_speed_input(qtbot, window, "2,5", "0,5", "1,000")
    (made,) = maker.fields.inputs()
    assert made.default == "2,5" and made.minimum == "0,5" and made.maximum == 1000
    qtbot.waitUntil(lambda: any("'0,5' is not a number" in problem for problem in maker.problems), timeout=5000)
    assert not maker.save_button.isEnabled()
