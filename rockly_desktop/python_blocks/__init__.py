"""Python back to blocks: Python text (what Rockly's generators write, and edits of it) turned into a
Rockly workspace, with what blocks cannot say kept verbatim in Python blocks. No Qt; uses profiles and core.

``convert.python_to_program`` is the entry (it also keeps the text's comments); ``source`` reads and refuses
bad input, ``templates`` matches the profile's and the packs' block templates, ``expressions`` and
``statements`` Blockly's standard blocks, ``literals`` the literals and names Rockly writes, ``workspace``
builds the block JSON.
"""
