"""The Bake and Remove operators. The modules that do the work (and numpy) load on first use."""
import bpy


def _targets(context):
    settings = context.scene.radbake
    objects = context.selected_objects if settings.scope == 'SELECTION' else context.scene.objects
    return [o for o in objects if o.type == 'MESH']


class RADBAKE_OT_bake(bpy.types.Operator):
    """Bake radiosity lightmaps with radbake and bring them back onto the objects (Esc cancels)"""

    bl_idname = "radbake.bake"
    bl_label = "Bake"
    bl_options = {'REGISTER'}

    _bake = None
    _timer = None
    _targets = None

    def _begin(self, context):
        from . import results, runner
        targets = _targets(context)
        if not targets:
            raise runner.BakeError("nothing selected: select the mesh objects to bake, or bake the whole scene"
                                   if context.scene.radbake.scope == 'SELECTION' else "the scene has no mesh objects")
        bake = runner.Bake(context)
        try:
            with results.earlier_bake_set_aside():
                bake.export(context)
            bake.start(context.scene.radbake)
        except Exception:
            bake.cleanup()
            raise
        return bake, targets

    def _finish(self, context, bake, targets):
        from . import results
        try:
            bake.check()
            results.apply(results.BakedScene(bake.output), targets, context.scene.radbake.bring_back)
            if context.scene.radbake.standard_view:
                results.use_standard_view(context.scene)
        finally:
            bake.cleanup()
        self.report({'INFO'}, "radbake: baked %d objects" % len(targets))

    def execute(self, context):
        """From scripts: the whole bake, synchronously."""
        from .runner import BakeError
        try:
            bake, targets = self._begin(context)
            bake.wait()
            self._finish(context, bake, targets)
        except BakeError as e:
            self.report({'ERROR'}, "radbake: " + str(e))
            return {'CANCELLED'}
        except Exception as e:  # a bug of ours: say so, but leave the scene as it was
            self.report({'ERROR'}, "radbake: %s" % e)
            return {'CANCELLED'}
        return {'FINISHED'}

    def invoke(self, context, event):
        """From the UI: bake in the background, progress in the status bar, Esc cancels."""
        from .runner import BakeError
        try:
            self._bake, self._targets = self._begin(context)
        except BakeError as e:
            self.report({'ERROR'}, "radbake: " + str(e))
            return {'CANCELLED'}
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.progress_begin(0, 1000)
        wm.modal_handler_add(self)
        return {'RUNNING_MODAL'}

    def _end_modal(self, context):
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)

    def modal(self, context, event):
        if event.type == 'ESC':
            self._end_modal(context)
            self._bake.cleanup()
            self.report({'WARNING'}, "radbake: bake cancelled; nothing was changed")
            return {'CANCELLED'}
        if event.type != 'TIMER':
            return {'PASS_THROUGH'}
        done = self._bake.poll()
        context.window_manager.progress_update(int(1000 * self._bake.fraction))
        context.workspace.status_text_set("radbake: %s %d%%  (Esc cancels)" % (self._bake.stage, int(100 * self._bake.fraction)))
        if not done:
            return {'PASS_THROUGH'}
        self._end_modal(context)
        try:
            self._finish(context, self._bake, self._targets)
        except Exception as e:
            self.report({'ERROR'}, "radbake: " + str(e))
            return {'CANCELLED'}
        return {'FINISHED'}


class RADBAKE_OT_remove(bpy.types.Operator):
    """Remove everything radbake added (UV map, colours, lightmap images and materials) and restore the materials and the view"""

    bl_idname = "radbake.remove"
    bl_label = "Remove bake"
    bl_options = {'REGISTER', 'UNDO'}

    def execute(self, context):
        from . import results
        results.remove([o for o in context.scene.objects if o.type == 'MESH'])
        results.restore_view(context.scene)
        return {'FINISHED'}
