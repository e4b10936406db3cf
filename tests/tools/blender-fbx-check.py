# Run by blender-fbx-check inside Blender: imports the FBX and writes a one-line JSON summary.
import json
import sys

import bpy

args = sys.argv[sys.argv.index('--') + 1:]
summary_path = args[0]
frames, json_out, path = None, None, None
i = 1
while i < len(args):
    if args[i] == '--frames':
        frames = [int(f) for f in args[i + 1].split(',')]
        i += 2
    elif args[i] == '--json-out':
        json_out = args[i + 1]
        i += 2
    else:
        path = args[i]
        i += 1

summary = {'ok': False, 'file': path}
try:
    bpy.ops.wm.read_factory_settings(use_empty=True)
    # Time 0 on frame 0 (the importer's default puts it on frame 1).
    result = bpy.ops.import_scene.fbx(filepath=path, anim_offset=0.0)
    if 'FINISHED' not in result:
        raise RuntimeError('the importer returned %s' % (result,))
    scene = bpy.context.scene
    objects = list(bpy.data.objects)
    armatures = [o for o in objects if o.type == 'ARMATURE']
    skinned = [o for o in objects if o.type == 'MESH' and any(m.type == 'ARMATURE' and m.object for m in o.modifiers)]
    # An agent's root: agent_<id>_<type> (its armature), the agent_* object no other agent_* holds.
    roots = [o for o in objects if o.name.startswith('agent_') and not (o.parent and o.parent.name.startswith('agent_'))]
    fps = scene.render.fps / scene.render.fps_base
    ranges = [tuple(a.frame_range) for a in bpy.data.actions]
    if frames is None:
        last = int(max(r[1] for r in ranges)) if ranges else 0
        frames = [0, last // 2, last]
    # Per agent and frame: its root's place and scale, and the middle of its skinned body
    # as the armature deforms it (Y-up: x, z, -y of Blender's).
    bodies = {o.name: [m for m in skinned if m.find_armature() == o] for o in roots}
    places = {}
    for f in frames:
        scene.frame_set(f)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        for o in roots:
            t = o.matrix_world.translation
            place = [t.x, t.z, -t.y, o.matrix_world.to_scale().x]
            total, count = [0.0, 0.0, 0.0], 0
            for m in bodies[o.name]:
                evaluated = m.evaluated_get(depsgraph)
                mesh = evaluated.to_mesh()
                for v in mesh.vertices:
                    w = evaluated.matrix_world @ v.co
                    total[0] += w.x; total[1] += w.z; total[2] -= w.y
                    count += 1
                evaluated.to_mesh_clear()
            places.setdefault(o.name, {})[str(f)] = place + ([c / count for c in total] if count else [])
    summary.update({
        'ok': True,
        'fps': fps,
        'objects': len(objects),
        'armatures': len(armatures),
        'skinnedMeshes': len(skinned),
        'actions': len(bpy.data.actions),
        'frameRange': [min(r[0] for r in ranges), max(r[1] for r in ranges)] if ranges else None,
        'agents': len(roots),
        'lamps': len([o for o in objects if o.name.startswith('set_lamp_')]),
        'set': any(o.name == 'set' for o in objects),
    })
    print('blender-fbx-check: %d agents, %d armatures, %d skinned meshes, %d actions at %g fps'
          % (len(roots), len(armatures), len(skinned), len(bpy.data.actions), fps))
    if json_out:
        with open(json_out, 'w') as f:
            json.dump(dict(summary, places=places), f)
except Exception as e:  # the import failed: say why
    summary['error'] = str(e)
with open(summary_path, 'w') as f:
    f.write(json.dumps(summary) + '\n')
