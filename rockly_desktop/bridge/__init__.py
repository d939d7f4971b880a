"""The Blockly editor page and its one JSON channel to Python (QWebChannel)."""
