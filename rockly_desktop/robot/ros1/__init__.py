"""The ROS 1 backend: the only part of Rockly that imports rospy, genpy or genmsg.

``message_classes`` finds ROS message, service and action classes (installed packages
first, then definitions a robot profile ships as data, generated with genpy into a cache by
``message_generation``); ``message_values`` converts Rockly's plain dicts to genpy messages
and back.
"""
