# SPDX-License-Identifier: GPL-3.0-or-later
"""A stand-in for the four pymeshlab calls of README's pymeshlab example, used only where
pymeshlab itself is absent (it is not in Debian), so the meshbridge half of the example still
runs. Files are read and written with meshbridge; the real MeshSet reads with vcglib."""

import meshbridge
import numpy as np


class Mesh:
    def __init__(self, vertex_matrix, face_matrix):
        self._v = np.asarray(vertex_matrix, dtype=np.float64)
        self._f = np.asarray(face_matrix, dtype=np.int32)

    def vertex_matrix(self):
        return self._v

    def face_matrix(self):
        return self._f

    def vertex_number(self):
        return len(self._v)

    def face_number(self):
        return len(self._f)


class MeshSet:
    def __init__(self):
        self._meshes = []

    def load_new_mesh(self, path):
        soup = meshbridge.read(path)
        self._meshes.append(Mesh(soup.vertices, soup.faces))

    def add_mesh(self, mesh, mesh_name=""):
        self._meshes.append(mesh)

    def current_mesh(self):
        return self._meshes[-1]

    def save_current_mesh(self, path):
        mesh = self.current_mesh()
        meshbridge.write(path, mesh.vertex_matrix(), mesh.face_matrix())
