"""dinam in Blender: simulate the selected meshes as flexible structures and play the motion.

The panel (3D View > Sidebar > dinam) takes the selected mesh objects, a material (a preset or its
values), pins from a vertex group (each object may have its own material and pins, and a vertex
group tied to another object, in the panel's "This object" box), gravity and wind; Estimate asks
`dinam info` how long and how much memory a run would take; Simulate writes each object as OBJ
and a scene file named after the .blend (with each object's colour or texture and shading),
says dinam's estimate, runs `dinam simulate` on them as a separate program (a progress bar and a
Cancel button while it runs; Esc cancels too), and gives each object a Mesh Cache modifier on its
point cache. The frames are the scene's: its frame range at its frame rate. Each .blend file's
run has a folder of its own within the panel's folder (named after the file), and a folder that
holds another file's run is refused, so that no file's cache plays another's motion.
"""
import os

import bpy

from . import cache_attach, dinam_run, scene_export

bl_info = {
    "name": "dinam",
    "author": "dinam",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "3D View > Sidebar > dinam",
    "description": "Simulate meshes as flexible structures (rigid bar spring model) with dinam",
    "category": "Physics",
}


class DinamSettings(bpy.types.PropertyGroup):
    program: bpy.props.StringProperty(
        name="dinam", description="The dinam program (a path, or a name on PATH)",
        default="dinam", subtype="FILE_PATH")
    folder: bpy.props.StringProperty(
        name="Folder", description="Where the OBJ files, the scene and the cache go",
        default="//dinam", subtype="DIR_PATH")
    preset: bpy.props.EnumProperty(
        name="Material",
        items=[(key, v[0], v[1]) for key, v in scene_export.PRESETS.items()] +
              [("CUSTOM", "Custom wire", "A wire of the density, modulus and radius below")],
        default="cotton")
    density: bpy.props.FloatProperty(name="Density (kg/m³)", default=1200.0, min=1e-3)
    youngs_modulus: bpy.props.FloatProperty(name="Young's modulus (Pa)", default=2.0e7, min=1e-3)
    radius: bpy.props.FloatProperty(name="Wire radius (m)", default=0.001, min=1e-6,
                                    precision=4)
    damping_ratio: bpy.props.FloatProperty(name="Damping ratio", default=0.05, min=0.0, max=1.0)
    pin_group: bpy.props.StringProperty(
        name="Pins", description="Vertex group whose vertices (weight above 0.5) never move")
    gravity: bpy.props.FloatVectorProperty(name="Gravity (m/s²)", default=(0.0, 0.0, -9.81))
    wind: bpy.props.FloatVectorProperty(name="Wind (m/s)", default=(0.0, 0.0, 0.0))
    turbulence: bpy.props.FloatProperty(
        name="Turbulence (m/s)", default=0.0, min=0.0,
        description="The wind's turbulence, RMS per component (with a wind)")
    gust: bpy.props.FloatProperty(
        name="Gusts (m/s)", default=0.0, min=0.0,
        description="Gusts along the wind, a 4 s sine of this amplitude (with a wind)")
    ground: bpy.props.BoolProperty(name="Ground", default=True,
                                   description="A ground plane the objects land on")
    ground_height: bpy.props.FloatProperty(name="Ground height (m)", default=0.0)
    floor: bpy.props.PointerProperty(
        name="Floor", type=bpy.types.Object,
        description="The ground at the top of this object's bounds, instead of the height")
    collider_radius: bpy.props.FloatProperty(
        name="Collider shell (m)", default=0.01, min=1e-4, precision=4,
        description="How far from its surface a collider pushes: a shell thick enough that a "
                    "falling cloth cannot pass it within one step")
    self_contact: bpy.props.BoolProperty(
        name="Self-contact", default=False,
        description="Each object collides with itself (a cloth that folds, a rope that coils)")
    settle: bpy.props.BoolProperty(
        name="Settle first", default=False,
        description="Start from the shape the objects rest in under gravity")
    progress: bpy.props.FloatProperty(name="Progress", subtype="PERCENTAGE", min=0, max=100)
    running: bpy.props.BoolProperty(default=False)
    # What dinam said in the last run (its warnings and notes, its summary), shown in the panel.
    last_report: bpy.props.StringProperty(default="")
    cancel_requested: bpy.props.BoolProperty(default=False)


def pin_group_of(obj, settings):
    """The vertex group that pins `obj`: its own (Object properties), else the panel's."""
    return obj.dinam_pin_group or settings.pin_group


def blend_stem():
    """The .blend file's name without its extension; "untitled" before it is saved."""
    return os.path.splitext(os.path.basename(bpy.data.filepath))[0] if bpy.data.filepath \
        else "untitled"


# The file in a run's folder that names the .blend whose run it holds.
OWNER_FILE = "blend_file.txt"


def run_folder(settings):
    """Where this .blend's run goes: the panel's folder, and within it a folder named after the
    saved .blend; refused (ExportError) where it holds another file's run."""
    folder = bpy.path.abspath(settings.folder)
    if bpy.data.filepath:
        folder = os.path.join(folder, scene_export.object_file_stem(blend_stem()))
    owner = os.path.abspath(bpy.data.filepath) if bpy.data.filepath else "(unsaved)"
    marker = os.path.join(folder, OWNER_FILE)
    if os.path.exists(marker):
        with open(marker) as f:
            other = f.read().strip()
        if other != owner:
            raise scene_export.ExportError(
                f"the folder '{folder}' holds the run of {other}, whose cache would then play "
                f"this file's motion: choose another folder in the panel (for each .blend, "
                f"dinam's files go into a folder named after it)")
    os.makedirs(folder, exist_ok=True)
    with open(marker, "w") as f:
        f.write(owner + "\n")
    return folder


def attach_of(obj, exported):
    """The object's tie to another (its Object properties' vertex group and target), as
    (vertex indices, target's name), or None; ExportError where the target is not simulated."""
    group, target = obj.dinam_attach_group, obj.dinam_attach_to
    if not group and target is None:
        return None
    if not group or target is None:
        raise scene_export.ExportError(
            f"'{obj.name}' has a dinam tie without its {'target' if group else 'vertex group'}: "
            "give both in its Object properties (Tie group, Tie to), or clear both")
    if obj.vertex_groups.get(group) is None:
        raise scene_export.ExportError(
            f"'{obj.name}' has no vertex group '{group}' to tie (its groups: "
            f"{', '.join(g.name for g in obj.vertex_groups) or 'none'})")
    if target == obj or target not in exported:
        raise scene_export.ExportError(
            f"'{obj.name}' is tied to '{target.name}', which is not simulated: select it too, or "
            "mark it as a dinam collider")
    indices = scene_export.pinned_indices(obj, group)
    if not indices:
        raise scene_export.ExportError(
            f"no vertex of '{obj.name}''s group '{group}' weighs above 0.5: nothing to tie")
    return indices, target.name


class Simulation:
    """One run: the files written, dinam running (its estimate first), and the objects to attach
    its motion to; with `simulate` False, the estimate alone."""

    def __init__(self, context, simulate=True):
        settings = context.scene.dinam
        self.objects = [o for o in context.selected_objects if o.type == "MESH"]
        if not self.objects:
            raise scene_export.ExportError("select the mesh objects to simulate")
        program = dinam_run.find_dinam(bpy.path.abspath(settings.program))
        if program is None:
            raise scene_export.ExportError(
                f"cannot find the dinam program '{settings.program}': set its path in the panel")
        if settings.folder.startswith("//") and not bpy.data.filepath:
            raise scene_export.ExportError(
                f"the folder '{settings.folder}' is relative to the .blend file, which is not saved "
                "yet: save the file first, or choose a folder for dinam's files in the panel")
        folder = run_folder(settings)
        inputs = os.path.join(folder, "input")
        os.makedirs(inputs, exist_ok=True)
        described = []
        stems = set()
        self.notes = []  # what to say before dinam runs
        for obj in self.objects:
            scene_export.check_mesh(obj)
        for obj in self.objects:
            group = pin_group_of(obj, settings)
            if group and obj.vertex_groups.get(group) is None:
                where = ("its Object properties' dinam pins" if obj.dinam_pin_group
                         else "the panel's Pins")
                raise scene_export.ExportError(
                    f"'{obj.name}' has no vertex group '{group}' (its groups: "
                    f"{', '.join(g.name for g in obj.vertex_groups) or 'none'}): choose the "
                    f"pins' group in {where}, or clear it to let the object fall freely")
        # Obstacles: the scene's mesh objects marked as colliders (Object properties), not
        # selected: they push and are not moved by the cloth; one that the animation moves (its
        # keys, parents, armature, shape keys) follows its track, frame by frame.
        self.colliders = [o for o in context.scene.objects
                          if o.type == "MESH" and o.dinam_collider and o not in self.objects]
        colliders = []
        for obj in self.colliders:
            stem = scene_export.object_file_stem(obj.name, stems)
            path = os.path.join(inputs, stem + ".obj")
            track = scene_export.collider_track(context, obj)
            look = scene_export.object_look(obj, inputs, stem)
            scene_export.write_obj(obj, path, track[0] if track else None, "texture" in look)
            track_path = None
            if track:
                track_path = os.path.join(inputs, stem + ".pc2")
                scene_export.write_pc2(track_path, track)
            colliders.append({"name": obj.name, "obj": path, "track": track_path, "look": look})
        exported = set(self.objects) | set(self.colliders)
        for obj in self.objects:
            stem = scene_export.object_file_stem(obj.name, stems)
            path = os.path.join(inputs, stem + ".obj")
            look = scene_export.object_look(obj, inputs, stem)
            scene_export.write_obj(obj, path, uvs="texture" in look)
            group = pin_group_of(obj, settings)
            pinned = scene_export.pinned_indices(obj, group)
            if not pinned:
                self.notes.append(
                    f"'{obj.name}' has no pinned vertex"
                    + (f" (no vertex of '{group}' weighs above 0.5)"
                       if group else " (no Pins group chosen)")
                    + ": it falls freely")
            preset = obj.dinam_preset if obj.dinam_preset in scene_export.PRESETS else None
            tie = attach_of(obj, exported)
            described.append({"name": obj.name, "obj": path, "pins": pinned, "preset": preset,
                              "look": look, "attach": [tie] if tie else []})
        scene = context.scene
        fps = scene.render.fps / scene.render.fps_base
        frames = scene.frame_end - scene.frame_start + 1
        scene_file = os.path.join(inputs, "scene.yaml")
        with open(scene_file, "w") as f:
            f.write(scene_export.scene_text(settings, described, frames, fps, colliders,
                                            blend_stem()))
        self.cache = os.path.join(folder, "cache")
        self.local = os.path.join(folder, "local")
        try:
            self.run = dinam_run.DinamRun(program, scene_file, self.cache, simulate=simulate)
        except OSError as e:  # it exists, but the system cannot run it
            raise scene_export.ExportError(
                f"cannot run the dinam program '{program}': {e.strerror or e}; set the path of a "
                "dinam built on this machine in the panel") from None

    def estimate_lines(self):
        """The estimate dinam gave before running, as a line for the panel (none before it has)."""
        estimate = self.run.estimate
        return [dinam_run.estimate_text(estimate)] if estimate is not None else []

    def finish(self, context, code):
        """Attaches the cache after a successful run; returns an error message or None."""
        if code != 0:
            said = self.run.message().strip()
            return said or f"dinam stopped with exit code {code}"
        try:
            cache_attach.attach(context, self.objects, self.cache, self.local)
        except cache_attach.AttachError as e:
            return str(e)
        return None


class DINAM_OT_simulate(bpy.types.Operator):
    """Simulate the selected meshes with dinam and play the motion with Mesh Cache modifiers"""

    bl_idname = "dinam.simulate"
    bl_label = "Simulate"
    bl_options = {"REGISTER"}

    _timer = None
    _simulation = None
    _cancelling = False
    _estimate_shown = False

    @classmethod
    def poll(cls, context):
        return not context.scene.dinam.running

    def start(self, context):
        try:
            self._simulation = Simulation(context)
        except scene_export.ExportError as e:
            self.report({"ERROR"}, str(e))
            return False
        for note in self._simulation.notes:
            self.report({"WARNING"}, "dinam: " + note)
        context.scene.dinam.last_report = "\n".join(self._simulation.notes)
        return True

    def end(self, context, code):
        error = self._simulation.finish(context, code)
        said = [line for line in self._simulation.run.lines if line.strip()]
        context.scene.dinam.last_report = "\n".join(
            self._simulation.notes + self._simulation.estimate_lines() + said)
        if error:
            self.report({"ERROR"}, error)
            return {"CANCELLED"}
        # dinam's warnings (a mesh's degenerate faces, a material far from real ones, …) reach the
        # artist after every run, not only when it fails.
        for line in said:
            if "warning:" in line:
                self.report({"WARNING"}, line)
        count = len(self._simulation.objects)
        self.report({"INFO"}, f"dinam: {count} object{'s' if count != 1 else ''} simulated"
                              + (f"; {len(said)} lines from dinam in the panel" if said else ""))
        return {"FINISHED"}

    # From a script or in the background: waits for dinam.
    def execute(self, context):
        if not self.start(context):
            return {"CANCELLED"}
        return self.end(context, self._simulation.run.wait())

    # From the panel: dinam runs while Blender stays responsive.
    def invoke(self, context, _event):
        if not self.start(context):
            return {"CANCELLED"}
        settings = context.scene.dinam
        settings.running, settings.cancel_requested, settings.progress = True, False, 0.0
        self._cancelling = self._estimate_shown = False
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.2, window=context.window)
        wm.modal_handler_add(self)
        wm.progress_begin(0, 100)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        settings = context.scene.dinam
        if event.type == "ESC" or settings.cancel_requested:
            # Never waits here: dinam is asked to stop, and the timer below sees it end (killed
            # after a grace period if it does not), so Blender's interface never freezes.
            self._simulation.run.request_cancel()
            self._cancelling = True
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        code = self._simulation.run.poll()
        if not self._estimate_shown and self._simulation.run.estimate is not None:
            # Before the motion: how long and how much memory the run will take.
            self._estimate_shown = True
            line = self._simulation.estimate_lines()[0]
            self.report({"INFO"}, "dinam " + line)
            settings.last_report = "\n".join(self._simulation.notes + [line])
        if self._cancelling and code is not None:
            self.stop(context)
            self.report({"WARNING"}, "dinam: cancelled; the objects are as they were")
            return {"CANCELLED"}
        settings.progress = 100.0 * self._simulation.run.fraction
        context.window_manager.progress_update(settings.progress)
        for area in context.screen.areas:
            if area.type == "VIEW_3D":
                area.tag_redraw()
        if code is None:
            return {"PASS_THROUGH"}
        self.stop(context)
        return self.end(context, code)

    def stop(self, context):
        settings = context.scene.dinam
        settings.running = False
        context.window_manager.event_timer_remove(self._timer)
        context.window_manager.progress_end()


class DINAM_OT_estimate(bpy.types.Operator):
    """Ask dinam how long and how much memory simulating the selected meshes would take, without
    simulating"""

    bl_idname = "dinam.estimate"
    bl_label = "Estimate"

    @classmethod
    def poll(cls, context):
        return not context.scene.dinam.running

    def execute(self, context):
        try:
            simulation = Simulation(context, simulate=False)
        except scene_export.ExportError as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        code = simulation.run.wait()  # `dinam info` reads the scene and estimates; no motion
        settings = context.scene.dinam
        if code != 0 or simulation.run.estimate is None:
            self.report({"ERROR"}, simulation.run.message().strip() or
                        f"dinam info stopped with exit code {code}")
            return {"CANCELLED"}
        lines = simulation.notes + simulation.estimate_lines()
        settings.last_report = "\n".join(lines)
        self.report({"INFO"}, "dinam " + simulation.estimate_lines()[0])
        return {"FINISHED"}


class DINAM_OT_cancel(bpy.types.Operator):
    """Stop the running simulation; the objects keep what they had"""

    bl_idname = "dinam.cancel"
    bl_label = "Cancel"

    def execute(self, context):
        context.scene.dinam.cancel_requested = True
        return {"FINISHED"}


class DINAM_PT_panel(bpy.types.Panel):
    bl_label = "dinam"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "dinam"

    def draw(self, context):
        settings = context.scene.dinam
        layout = self.layout
        layout.prop(settings, "program")
        layout.prop(settings, "folder")
        layout.prop(settings, "preset")
        column = layout.column()
        column.enabled = settings.preset == "CUSTOM"
        for key in ("density", "youngs_modulus", "radius"):
            column.prop(settings, key)
        layout.prop(settings, "damping_ratio")
        obj = context.active_object
        if obj is not None and obj.type == "MESH":
            layout.prop_search(settings, "pin_group", obj, "vertex_groups")
        layout.prop(settings, "gravity")
        layout.prop(settings, "wind")
        layout.prop(settings, "turbulence")
        layout.prop(settings, "gust")
        layout.prop(settings, "ground")
        row = layout.row()
        row.enabled = settings.ground and settings.floor is None
        row.prop(settings, "ground_height")
        row = layout.row()
        row.enabled = settings.ground
        row.prop(settings, "floor")
        layout.prop(settings, "self_contact")
        layout.prop(settings, "settle")
        layout.prop(settings, "collider_radius")
        if obj is not None and obj.type == "MESH":
            box = layout.box()
            box.label(text=f"This object: {obj.name}")
            box.prop(obj, "dinam_collider")
            row = box.row()
            row.enabled = not obj.dinam_collider
            row.prop(obj, "dinam_preset")
            row = box.row()
            row.enabled = not obj.dinam_collider
            row.prop_search(obj, "dinam_pin_group", obj, "vertex_groups")
            row = box.row()
            row.enabled = not obj.dinam_collider
            row.prop_search(obj, "dinam_attach_group", obj, "vertex_groups")
            row = box.row()
            row.enabled = not obj.dinam_collider
            row.prop(obj, "dinam_attach_to")
        if settings.last_report and not settings.running:
            box = layout.box()
            box.label(text="Last run:")
            for line in settings.last_report.splitlines()[-12:]:
                box.label(text=line, icon="ERROR" if "warning:" in line else "INFO")
        if settings.running:
            row = layout.row()
            row.enabled = False
            row.prop(settings, "progress", slider=True)
            layout.operator("dinam.cancel", icon="CANCEL")
        else:
            row = layout.row()
            row.operator("dinam.estimate", icon="TIME")
            row.operator("dinam.simulate", icon="PHYSICS")


CLASSES = (DinamSettings, DINAM_OT_simulate, DINAM_OT_estimate, DINAM_OT_cancel, DINAM_PT_panel)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.dinam = bpy.props.PointerProperty(type=DinamSettings)
    bpy.types.Object.dinam_collider = bpy.props.BoolProperty(
        name="dinam collider", default=False,
        description="An obstacle for dinam's simulations: pushes the simulated objects, never moves")
    # Each simulated object may have a material and pins of its own (a cape of denim pinned at its
    # collar beside a flag of cotton pinned at its hoist); empty, the panel's.
    bpy.types.Object.dinam_preset = bpy.props.EnumProperty(
        name="dinam material",
        items=[("PANEL", "Panel's", "The material chosen in the dinam panel")] +
              [(key, v[0], v[1]) for key, v in scene_export.PRESETS.items()],
        default="PANEL")
    bpy.types.Object.dinam_pin_group = bpy.props.StringProperty(
        name="dinam pins",
        description="This object's vertex group whose vertices never move; empty: the panel's Pins")
    # Tied to another object (a cape's collar to a moving shoulder, a rope to a hook): the group's
    # vertices move with the target's nearest point.
    bpy.types.Object.dinam_attach_group = bpy.props.StringProperty(
        name="Tie group",
        description="This object's vertex group tied to the target object (weight above 0.5)")
    bpy.types.Object.dinam_attach_to = bpy.props.PointerProperty(
        name="Tie to", type=bpy.types.Object,
        description="The object the tie group moves with: simulated too, or a dinam collider")


def unregister():
    del bpy.types.Object.dinam_attach_to
    del bpy.types.Object.dinam_attach_group
    del bpy.types.Object.dinam_pin_group
    del bpy.types.Object.dinam_preset
    del bpy.types.Object.dinam_collider
    del bpy.types.Scene.dinam
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
