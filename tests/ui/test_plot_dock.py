"""The Plot dock in the window: drawn as soon as it shows, also when a restart brings it back on top."""
from window_tools import WindowDriver


def test_the_plot_dock_on_top_at_a_restart_shows_its_plot_without_switching_tabs(qtbot, driver, tmp_path):
    first = driver.open_window()
    first.plot_dock.raise_()
    qtbot.waitUntil(lambda: first._made_plot() is not None and first._made_plot().isVisible(), timeout=10000)
    first.close()
    again = WindowDriver(qtbot, driver.settings_path)
    try:
        window = again.open_window()
        qtbot.waitUntil(lambda: window.plot_dock.isVisible() and not window.plot_dock.visibleRegion().isEmpty(),
                        timeout=10000)
        qtbot.waitUntil(lambda: window._made_plot() is not None and window._made_plot().isVisible(), timeout=10000)
        assert window.plot_dock.widget() is window._made_plot()
    finally:
        again.close_all()
