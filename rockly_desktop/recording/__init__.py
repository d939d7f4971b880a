"""Recording runs to MCAP files and reading them back (no Qt, no ROS: a robot's encoder is handed in)."""
