"""OpenFAST floating models (``.fst``) -> floatmoor vessel, mooring and scene files.

:func:`import_openfast` (:mod:`.importer`) reads the files as OpenFAST reads them
(:mod:`.reader`, :mod:`.schemas`), builds every rigid mass (:mod:`.bodies`) and the mass budget
(:mod:`.budget`), maps the sea state (:mod:`.seastate`) and lists what it does not map.
"""

from .importer import OpenFASTImport, Unmapped, import_openfast
from .reader import InputFile

__all__ = ["InputFile", "OpenFASTImport", "Unmapped", "import_openfast"]
