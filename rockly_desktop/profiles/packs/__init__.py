"""Blocks made without code, and the block packs that hold them (issue 22). No Qt here.

A *made block* (``spec.MadeBlock``) is data: what it does (``kind``), the ROS interface it
uses, its inputs and fixed fields, its sentence in English and German, colour, category and
tooltip. ``validation.block_problems`` says what is wrong with one in the reader's language;
``generate`` turns one into an ordinary Blockly block definition whose Python template calls
the generic ``ros.*`` commands (so a teacher's limits, the safe stop, recording and stepping
apply as to every block).

A *block pack* (``pack.Pack``) is a folder in the user's data folder (``packs/ID/``) with a
manifest ``pack.yaml`` that says which robot profile it ``adds_to``, and ordinary
``blocks.yaml``/``toolbox.yaml`` files in the formats profiles use; ``made.yaml`` keeps each
made block's spec so the maker can show it again, and ``messages/`` the definitions of the types
its blocks use that Rockly knew only because the robot said them (they join the profile's
``message_folders``). ``making.save_block`` writes a block into a pack all-or-nothing;
``merge.with_packs`` puts installed packs into the profile they add to (the registry does this
when it discovers profiles, and again on ``reload_packs``); ``archive`` exports and imports a
pack as one zip file; ``interfaces`` lists the fields of the ROS types Rockly knows without a
robot; ``choices`` gives the profile's categories and colours to choose from and a block's
preview entry for the editor page.
"""
