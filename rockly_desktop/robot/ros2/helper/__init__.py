"""Rockly's ROS 2 helper process: everything that runs there, on ``.venv-ros2``'s Python with rclpy.

``node`` is the process (started by ``robot.ros2.client``); ``ros_values`` turns dicts into rclpy
messages and back, ``layouts`` gives Rockly's side a type's layout to encode with, ``qos`` picks a
topic's QoS, ``topic_reader`` reads the subscriptions, ``sim_serving`` serves a simulator's services
and actions. Of Rockly it imports only ``robot.ros2.wire``; Rockly's side never imports this package
(it runs in another process, with another Python).
"""
