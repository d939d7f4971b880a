"""The block maker (issue 22): a dialog that makes a block from what the robot offers, without code.

``offers`` lists the topics, services, actions and parameters to make a block from (the robot's
live graph, or the types Rockly knows without a robot); ``field_table`` is the table of a type's
fields, each an input of the block, a fixed value or left at its default; ``preview`` draws the
block on an editor page of its own; ``maker_dialog`` puts them together, checks the block with
``profiles.packs.validation`` as it is typed and saves it into a block pack. The window reads the
packs again after a save (``registry.reload_packs``) so the block is in the toolbox at once.
"""
