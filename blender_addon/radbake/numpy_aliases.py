"""numpy's old type aliases for Blender 3.4's glTF importer, on numpy 1.24 and later 1.x.

Debian 12 ships Blender 3.4 with its own numpy 1.24, which removed np.bool, np.int, np.float,
np.complex, np.object and np.str (deprecated since 1.20 as plain copies of the builtins). Blender's
bundled importer still calls np.bool, so every glTF with normals fails with "module 'numpy' has no
attribute 'bool'"; Blender's own builds bundle an older numpy and never see it. Each missing alias
is put back as the builtin it always was; aliases numpy has (all of them before 1.24, np.bool as
numpy's own scalar from 2.0 on) are left alone.

The radbake add-on does this when it is enabled. Without the add-on, this one file is enough:
- copy it into Blender's startup scripts folder (~/.config/blender/3.4/scripts/startup/ on Linux),
  which Blender loads on every start except with --factory-startup; or
- run it for one session: blender --python numpy_aliases.py
"""
import builtins
import warnings

REMOVED_IN_NUMPY_1_24 = ("bool", "int", "float", "complex", "object", "str")


def restore():
    """Puts back the aliases this numpy lacks; returns their names."""
    import numpy
    restored = []
    with warnings.catch_warnings():
        # numpy 1.24 warns that np.bool and np.str will become its own scalars on the very lookup
        # that tells they are missing.
        warnings.simplefilter("ignore", FutureWarning)
        for name in REMOVED_IN_NUMPY_1_24:
            if not hasattr(numpy, name):
                setattr(numpy, name, getattr(builtins, name))
                restored.append(name)
    return restored


def register():
    """Blender calls this for a startup script."""
    restore()


def unregister():
    """The aliases stay: taking them away would break the session's next glTF import again."""


if __name__ == "__main__":
    print("numpy aliases restored:", ", ".join(restore()) or "none were missing")
