"""Running the program on screen: the run session, its toolbar, its messages, the blocks' badges and the
recordings every run leaves."""
