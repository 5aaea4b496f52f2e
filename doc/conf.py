# Sphinx configuration for the ETD-DPD command pages (python3-sphinx from Debian).
#
#   LAMMPS_SOURCE_DIR=/path/to/lammps sphinx-build -W -b html doc build/doc-html
#
# With a LAMMPS source tree, the pages build as they would in the LAMMPS manual: LAMMPS's own
# lexer for `code-block:: LAMMPS`, its table_from_list directive, and its theme where the tree
# has one (newer LAMMPS; sphinx_rtd_theme otherwise, as older manuals used). A :doc: link to a
# LAMMPS command (fix_nve, neigh_modify, ...) becomes a link into docs.lammps.org, but only if
# that page exists in the tree's doc/src, so a mistyped page name still fails under -W.
import os
import sys

project = 'ETD-DPD'
author = 'ETD-DPD developers'
root_doc = 'index'
source_suffix = {'.rst': 'restructuredtext'}
exclude_patterns = ['_build', '_ext']
highlight_language = 'none'
extensions = ['sphinx.ext.mathjax']

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '_ext'))
extensions.append('lammps_links')

lammps_source = os.environ.get('LAMMPS_SOURCE_DIR', '')
lammps_doc = os.path.join(lammps_source, 'doc') if lammps_source else ''
lammps_manual_url = 'https://docs.lammps.org/'
lammps_pages = set()
html_theme = 'alabaster'

if lammps_doc and os.path.isdir(os.path.join(lammps_doc, 'src')):
    lammps_pages = {name[:-4] for name in os.listdir(os.path.join(lammps_doc, 'src'))
                    if name.endswith('.rst')}
    sphinx_config = os.path.join(lammps_doc, 'utils', 'sphinx-config')
    sys.path.append(os.path.join(lammps_doc, 'src', '_ext'))  # newer trees
    sys.path.append(sphinx_config)                            # 29Sep2021 keeps them here
    try:
        import table_from_list  # noqa: F401  (LAMMPS's directive, used by its manual)
        extensions.append('table_from_list')
    except ImportError:
        pass
    try:
        import LAMMPSLexer
        from sphinx.highlighting import lexers
        lexers['LAMMPS'] = LAMMPSLexer.LAMMPSLexer(startinline=True)
    except ImportError:
        pass
    if os.path.isdir(os.path.join(sphinx_config, '_themes', 'lammps_theme')):
        html_theme = 'lammps_theme'
        html_theme_path = [os.path.join(sphinx_config, '_themes')]
        sys.path.append(os.path.join(sphinx_config, '_themes'))
if html_theme == 'alabaster':
    try:
        import sphinx_rtd_theme  # noqa: F401  (Debian: python3-sphinx-rtd-theme)
        html_theme = 'sphinx_rtd_theme'
    except ImportError:
        pass
html_title = 'ETD-DPD commands'
