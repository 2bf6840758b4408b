# sourced (POSIX sh): relocates the bundled Debian Open MPI 4.1 / PMIx to $RF_HOME
: "${RF_HOME:?RF_HOME must be set to the bundle root}"
export RF_HOME
# $RF_HOME/bin first: its gmsh stand-in serves the recorded cross-section meshes
case ":${PATH:-}:" in *":$RF_HOME/bin:"*) ;; *) PATH="$RF_HOME/bin:${PATH:-/usr/bin:/bin}" ;; esac
export PATH
unset LD_PRELOAD LD_LIBRARY_PATH OMPI_MCA_mca_base_param_files
export OPAL_PREFIX="$RF_HOME" OPAL_EXEC_PREFIX="$RF_HOME" OPAL_BINDIR="$RF_HOME/bin" \
  OPAL_LIBDIR="$RF_HOME/lib" OPAL_PKGLIBDIR="$RF_HOME/lib/openmpi3" \
  OPAL_DATAROOTDIR="$RF_HOME/share" OPAL_DATADIR="$RF_HOME/share" \
  OPAL_PKGDATADIR="$RF_HOME/share/openmpi" OPAL_SYSCONFDIR="$RF_HOME/etc" \
  OPAL_LIBEXECDIR="$RF_HOME/bin" OPAL_SBINDIR="$RF_HOME/bin"
export PMIX_PREFIX="$RF_HOME" PMIX_INSTALL_PREFIX="$RF_HOME" PMIX_EXEC_PREFIX="$RF_HOME" \
  PMIX_LIBDIR="$RF_HOME/lib" PMIX_PKGLIBDIR="$RF_HOME/lib/pmix" \
  PMIX_DATAROOTDIR="$RF_HOME/share" PMIX_DATADIR="$RF_HOME/share" \
  PMIX_PKGDATADIR="$RF_HOME/share/pmix" PMIX_SYSCONFDIR="$RF_HOME/etc" \
  PMIX_MCA_mca_base_component_path="$RF_HOME/lib/pmix" PMIX_MCA_gds=hash
export OMPI_MCA_mca_base_component_path="$RF_HOME/lib/openmpi3" \
  OMPI_MCA_mca_base_param_files="$RF_HOME/etc/openmpi-mca-params.conf" \
  OMPI_MCA_btl_vader_backing_directory="${TMPDIR:-/tmp}" \
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  HWLOC_PLUGINS_PATH="$RF_HOME/lib/hwloc-none" OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}" \
  OPENBLAS_NUM_THREADS=1
