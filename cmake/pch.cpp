// Anchors the precompiled header target (cmake/pch.hpp).
