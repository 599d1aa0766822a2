"""tools/cycles_pattern.py: sets Cycles' sampling pattern for a script that resets Blender's settings
itself (../shared/tools/cycles/cycles_ref.py starts from factory settings), run before it:
    CYCLES_PATTERN=SOBOL blender -b --factory-startup --python tools/cycles_pattern.py --python SCRIPT -- ARGS
A persistent handler survives the other script's reset and sets the pattern when the render starts;
it prints CYCLES_PATTERN and the pattern in force, which bench/cycles.sh checks. Why: Blender 3.4's
default pattern (progressive multi-jitter) renders scenes/many-lights 0.4-1.7 % too bright in its
direct light, depending on the sample count; with 'SOBOL' Cycles agrees with pathlab (bench/log.md,
"Many lights against Cycles: the 0.4 % explained")."""
import os
import bpy

PATTERN = os.environ.get('CYCLES_PATTERN', '')


@bpy.app.handlers.persistent
def set_pattern(scene, *_):
    if PATTERN:
        scene.cycles.sampling_pattern = PATTERN
    print('CYCLES_PATTERN', scene.cycles.sampling_pattern, flush=True)


bpy.app.handlers.render_pre.append(set_pattern)
