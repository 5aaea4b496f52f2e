"""Resolve :doc: links to LAMMPS's own command pages as links into the LAMMPS manual.

The ETD-DPD pages are written as if they sat in LAMMPS's doc/src (so that they can be copied
there unchanged); built on their own, a link such as :doc:`fix nve <fix_nve>` has no local
target. It is resolved here only when the LAMMPS tree named in conf.py has that page.
"""
from docutils import nodes


def resolve_lammps_page(app, env, node, contnode):
    if node.get('refdomain') != 'std' or node.get('reftype') != 'doc':
        return None
    target = node.get('reftarget', '')
    if target not in app.config.lammps_pages:
        return None
    reference = nodes.reference('', '', internal=False,
                                refuri=f'{app.config.lammps_manual_url}{target}.html',
                                reftitle=f'LAMMPS manual: {target}')
    reference.append(contnode)
    return reference


def setup(app):
    app.add_config_value('lammps_pages', set(), 'env')
    app.add_config_value('lammps_manual_url', 'https://docs.lammps.org/', 'env')
    app.connect('missing-reference', resolve_lammps_page)
    return {'parallel_read_safe': True, 'parallel_write_safe': True}
