"""Edits of a certificate (a JSON object) that the mutation campaigns share: a copy with one field
set or deleted, the field named by its path of keys and indices."""
import copy


def with_field(cert, path, value):
    c = copy.deepcopy(cert)
    o = c
    for k in path[:-1]:
        o = o[k]
    o[path[-1]] = value
    return c


def deleted(cert, path):
    c = copy.deepcopy(cert)
    o = c
    for k in path[:-1]:
        o = o[k]
    del o[path[-1]]
    return c
