"""Running the program on screen: the run session, its toolbar, its messages and the blocks' badges."""
