"""The operator window's parts: its pages, menus, docks, status bar and key routing."""
