"""The ROS 1 backend: the only part of Rockly that imports rospy, genpy or genmsg.

``messages`` finds ROS message, service and action classes (installed packages first,
then definitions a robot profile ships as data, generated with genpy into a cache) and
converts Rockly's plain dicts to genpy messages and back.
"""
