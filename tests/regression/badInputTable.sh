#!/bin/bash
# Bad-input table: every executable must refuse bad input cleanly.
# A base case per program is prepared once (mesh, fields) and checked to run;
# each case copies a base, breaks one thing, runs the program and checks
#   (1) a non-zero exit status,
#   (2) no crash: no signal, no segmentation fault / floating point exception
#       stack trace, no core file,
#   (3) the log names the file and the entry (or keyword / value) at fault,
#   (4) the input (time directories, constant/, system/) is untouched.
# One '>>' line per case, then '>> N cases, M failed'. The table of cases is
# doc/badInput.md.
. "$JWLIBFOAM_PROJECT/tests/regression/hostileInputBases.bash"

# ----------------------------------------------------------------- cases
nCases=0
nFailed=0
inputSum() {  # checksum of the input: time directories, constant, system
    find constant system [0-9]* -type f 2>/dev/null | sort | xargs -r md5sum | md5sum
}
prep() {  # name base: a fresh copy of the base; cwd = the copy
    rm -rf "$top/cases/$1"
    cp -r "$top/bases/$2" "$top/cases/$1"
    cd "$top/cases/$1" || exit 1
    rm -f log.*
}
check() {  # name file entry command...: run in the prepared copy and judge
    local name=$1 file=$2 entry=$3; shift 3
    local before after rc msg problems=""
    before=$(inputSum)
    "$@" > "log.$1" 2>&1
    rc=$?
    after=$(inputSum)
    local log="log.$1"
    msg=$(awk '/FOAM FATAL/ { f = 1; next } f && NF { print; exit }' "$log" \
          | sed 's/^ *//; s/ *$//' | cut -c1-100)
    [ $rc = 0 ] && problems="$problems exit status 0;"
    if [ $rc -ge 128 ] \
    || grep -v '^trapFpe' "$log" | grep -qiE 'segmentation|sigsegv|sigfpe|floating point exception|core dumped|stack trace' \
    || compgen -G 'core*' > /dev/null
    then
        problems="$problems crashed (exit $rc);"
    fi
    # file and entry must be named by the error message itself
    sed -n '/FOAM FATAL/,$p' "$log" > "$log.error"
    grep -qF -- "$file" "$log.error" || problems="$problems file '$file' not named;"
    grep -qF -- "$entry" "$log.error" || problems="$problems '$entry' not named;"
    [ "$before" = "$after" ] || problems="$problems input changed;"
    nCases=$((nCases + 1))
    if [ -z "$problems" ]; then
        echo ">> $name: ok ($msg)"
    else
        nFailed=$((nFailed + 1))
        echo ">> $name: ($msg)$problems  <-- FAIL"
        sed -n '/FOAM FATAL/,/FOAM exiting/p' "$log" | head -12 | sed 's/^/   /'
    fi
    cd "$top" || exit 1
}

# --- jwlIbFoam: constant/thermophysicalProperties
prep thermoMissingMaterials sod
sed -i '/^materials/d' constant/thermophysicalProperties
check thermoMissingMaterials thermophysicalProperties "'materials'" jwlIbFoam

prep thermoMisspeltGamma sod
sed -i 's/gamma 1.4/gama 1.4/' constant/thermophysicalProperties
check thermoMisspeltGamma thermophysicalProperties "'gama'" jwlIbFoam

prep thermoUnknownEquationOfState sod
sed -i 's/equationOfState idealGas/equationOfState idealGaz/' constant/thermophysicalProperties
check thermoUnknownEquationOfState thermophysicalProperties idealGaz jwlIbFoam

prep idealGasGammaOne sod
sed -i 's/gamma 1.4/gamma 1/' constant/thermophysicalProperties
check idealGasGammaOne thermophysicalProperties "'gamma'" jwlIbFoam

prep stiffenedGasNegativePInf sod
sed -i 's/equationOfState idealGas; gamma 1.4; Cv 718;/equationOfState stiffenedGas; gamma 4.4; pInf -6e8;/' \
    constant/thermophysicalProperties
check stiffenedGasNegativePInf thermophysicalProperties pInf jwlIbFoam

prep stiffenedGasNegativeCavitationPressure sod
sed -i 's/equationOfState idealGas; gamma 1.4; Cv 718;/equationOfState stiffenedGas; gamma 4.4; pInf 6e8; cavitationPressure -2300;/' \
    constant/thermophysicalProperties
check stiffenedGasNegativeCavitationPressure thermophysicalProperties "'cavitationPressure'" jwlIbFoam

prep stiffenedGasCavitationPressureWord sod
sed -i 's/equationOfState idealGas; gamma 1.4; Cv 718;/equationOfState stiffenedGas; gamma 4.4; pInf 6e8; cavitationPressure off;/' \
    constant/thermophysicalProperties
check stiffenedGasCavitationPressureWord thermophysicalProperties "'cavitationPressure'" jwlIbFoam

prep jwlOmegaZero tntCharged
sed -i 's/explosive       TNT;/explosive TNT; omega 0;/' constant/thermophysicalProperties
check jwlOmegaZero thermophysicalProperties "'omega'" jwlIbFoam

prep jwlNegativeRho0 tntCharged
sed -i 's/explosive       TNT;/explosive TNT; rho0 -1630;/' constant/thermophysicalProperties
check jwlNegativeRho0 thermophysicalProperties "'rho0'" jwlIbFoam

prep jwlUnknownExplosive tntCharged
sed -i 's/explosive       TNT;/explosive TNTX;/' constant/thermophysicalProperties
check jwlUnknownExplosive thermophysicalProperties "'TNTX'" jwlIbFoam

# --- jwlIbFoam: system/blastFluidProperties
prep unknownFlux sod
setEntry system/blastFluidProperties flux HLLX
check unknownFlux blastFluidProperties HLLX jwlIbFoam

prep unknownLimiter sod
setEntry system/blastFluidProperties limiter vanLeerr
check unknownLimiter blastFluidProperties vanLeerr jwlIbFoam

prep RKorder4 sod
setEntry system/blastFluidProperties RKorder 4
check RKorder4 blastFluidProperties "'RKorder'" jwlIbFoam

prep misspeltLimiter sod
sed -i 's/^limiter /limitter /' system/blastFluidProperties
check misspeltLimiter blastFluidProperties "'limitter'" jwlIbFoam

prep misspeltQSchemeCQ sod
sed -i 's/CQ 1.5/CQQ 1.5/' system/blastFluidProperties
check misspeltQSchemeCQ blastFluidProperties.QScheme "'CQQ'" jwlIbFoam

# --- jwlIbFoam: fields and controlDict
firstOne() {  # field value: replace the first '1' of the internalField list
    awk -v v="$2" '/^internalField/ { f = 1 } f && $0 == "1" && !done { print v; done = 1; next } 1' \
        "$top/bases/sod/0/$1" > "0/$1"
}
prep negativeRhoField sod
firstOne rho -1
check negativeRhoField "0/rho" "'internalField'" jwlIbFoam

prep zeroPField sod
firstOne p 0
check zeroPField "0/p" "'internalField'" jwlIbFoam

prep negativePPatch sod
foamDictionary -entry boundaryField.left -set '{ type fixedValue; value uniform -1; }' 0/p > /dev/null
check negativePPatch "0/p" "'boundaryField.left'" jwlIbFoam

prep alphaAboveOne tntCharged
sed -i '0,/^9.9999999999999995e-07$/s//1.5/' 0/alpha.products
check alphaAboveOne "0/alpha.products" "'internalField'" jwlIbFoam

prep maxCoTooLarge sod
setEntry system/controlDict maxCo 3
check maxCoTooLarge controlDict "'maxCo'" jwlIbFoam

prep maxDeltaTZero sod
setEntry system/controlDict maxDeltaT 0
check maxDeltaTZero controlDict "'maxDeltaT'" jwlIbFoam

prep negativeDeltaT sod
setEntry system/controlDict deltaT -1e-4
check negativeDeltaT controlDict "'deltaT'" jwlIbFoam

prep nanInP sod
awk '/^internalField/ { f = 1 } f && $0 == "1" && !done { print "nan"; done = 1; next } 1' \
    ../../bases/sod/0/p > 0/p
check nanInP "0/p" "'nan'" jwlIbFoam

prep missingU sod
rm 0/U
check missingU "0/U" "cannot find file" jwlIbFoam

prep missingEndTime sod
sed -i '/^endTime/d' system/controlDict
check missingEndTime controlDict "'endTime'" jwlIbFoam

# --- jwlIbFoam: restart from a damaged latest time
prep restartTruncatedP restart
f=0.02/p; head -c $(( $(stat -c %s $f) / 2 )) $f > $f.half && mv $f.half $f
check restartTruncatedP "0.02/p" "FOAM FATAL IO ERROR" jwlIbFoam

prep restartMissingP restart
rm 0.02/p
check restartMissingP "0.02/p" "cannot find file" jwlIbFoam

prep restartMissingRhoU restart
rm 0.02/rhoU
check restartMissingRhoU "time 0.02" "rhoU" jwlIbFoam

# --- jwlIbFoam with an immersed solid
prep solidOutsideFluid box
sed -i 's/centre (0.07 0.1)/centre (0.19 0.1)/' system/femdemMeshDict
femdemMesh > log.femdemMesh 2>&1
check solidOutsideFluid "constant/solidMesh" "outside the fluid mesh" jwlIbFoam

# The first-generation coupling (method fluidFraction) was removed: its
# method and its entries stop naming the entry and saying so
prep removedMethodFluidFraction box
sed -i 's/^method .*/method fluidFraction;/' constant/immersedBodyProperties
check removedMethodFluidFraction immersedBodyProperties "'method fluidFraction': the first-generation coupling" jwlIbFoam

prep removedBeta box
echo 'beta 1;' >> constant/immersedBodyProperties
check removedBeta immersedBodyProperties "'beta' was removed with the first-generation coupling" jwlIbFoam

prep removedMinFluidFraction box
echo 'minFluidFraction 0.02;' >> constant/immersedBodyProperties
check removedMinFluidFraction immersedBodyProperties "'minFluidFraction' was removed with the first-generation coupling" jwlIbFoam

prep removedCrackPressure box
echo 'crackPressure false;' >> constant/immersedBodyProperties
check removedCrackPressure immersedBodyProperties "'crackPressure' was removed with the first-generation coupling" jwlIbFoam

prep misspeltCrackVenting box
echo 'crackVentng false;' >> constant/immersedBodyProperties
check misspeltCrackVenting immersedBodyProperties "'crackVentng'" jwlIbFoam

prep unknownCouplingMethod box
sed -i 's/^method .*/method cutcell;/' constant/immersedBodyProperties
check unknownCouplingMethod immersedBodyProperties "'cutcell'" jwlIbFoam

prep coupledMissingMaterial box
sed -i 's/^    rock$/    granite/' constant/femdemProperties
check coupledMissingMaterial femdemProperties "'rock'" jwlIbFoam

prep restartFluidFractionOutOfRange boxRestart
sed -i '0,/^1$/s//1.5/' 4e-06/fluidFraction
check restartFluidFractionOutOfRange "4e-06/fluidFraction" "'internalField'" jwlIbFoam

# --- setCharge
prep chargeOutsideDomain tnt
sed -i 's/centre (0 0 0)/centre (5 5 0)/' system/setChargeDict
check chargeOutsideDomain setChargeDict "'charges'" setCharge

prep setChargeMissingRadius tnt
sed -i 's/ radius 0.05;//' system/setChargeDict
check setChargeMissingRadius setChargeDict "'radius'" setCharge

prep setChargeUnknownShape tnt
sed -i 's/circle {/ellipse {/' system/setChargeDict
check setChargeUnknownShape setChargeDict "'ellipse'" setCharge

prep setChargeUnknownExplosive tnt
sed -i 's/explosive       TNT;/explosive TNTX;/' constant/thermophysicalProperties
check setChargeUnknownExplosive thermophysicalProperties "'TNTX'" setCharge

prep setChargeOneMaterial tnt
sed -i 's/^materials (products air);/materials (air);/' constant/thermophysicalProperties
check setChargeOneMaterial thermophysicalProperties "'materials'" setCharge

# --- femdemFoam: constant/femdemProperties
femdemCase() {  # name sed-expression entry
    prep "$1" bar
    sed -i "$2" constant/femdemProperties
    check "$1" femdemProperties "$3" femdemFoam
}
femdemCase zeroE 's/E 10e9/E 0/' "'E'"
femdemCase nuHalf 's/nu 0.25/nu 0.5/' "'nu'"
femdemCase zeroRho 's/rho 2500/rho 0/' "'rho'"
femdemCase negativeGI 's/GI 20;/GI -20;/' "'GI'"
femdemCase misspeltTensileStrength 's/tensileStrength/tensilStrength/' "'tensileStrength'"
femdemCase missingMaterial 's/materials { rock/materials { granite/' "'rock'"
femdemCase unknownCohesiveLaw 's/cohesiveLaw munjiza/cohesiveLaw munjitza/' "'munjitza'"
femdemCase unknownContactLaw 's/contactLaw potential/contactLaw potentiall/' "'potentiall'"
femdemCase unknownElasticLaw 's/cohesiveLaw munjiza;/cohesiveLaw munjiza; elasticLaw neoHookian;/' "'neoHookian'"
femdemCase unknownMaterialElasticLaw 's/dampingRatio 0.1;/dampingRatio 0.1; elasticLaw linearElastic;/' "'linearElastic'"
femdemCase maxStrainIncrementZero 's/cohesiveLaw munjiza;/cohesiveLaw munjiza; maxStrainIncrement 0;/' "'maxStrainIncrement'"
femdemCase unknownBoundaryType 's/type velocity/type velocty/' "velocty"
femdemCase unknownBoundaryPatch 's/left { type fixed; }/lft { type fixed; }/' "'lft'"

# --- femdemFoam / femdemMeshCheck: constant/solidMesh
invertFirst='s/^(triangles\s+\d+ \( \( )(\d+) (\d+) (\d+)/$1$2 $4 $3/'
duplicateFirst='s/^(triangles\s+)(\d+) \( (\( \d+ \d+ \d+ \))/$1.($2+1)." ( $3 $3"/e; s/^(triangleMaterials\s+)(\d+)/$1.($2+1)/e'
prep solidMeshInverted bar
perl -pi -e "$invertFirst" constant/solidMesh
check solidMeshInverted solidMesh "triangle 0" femdemFoam

prep solidMeshDuplicateTriangle bar
perl -pi -e "$duplicateFirst" constant/solidMesh
check solidMeshDuplicateTriangle solidMesh "triangles 0 and 1" femdemFoam

prep solidMeshMaterialIndex bar
sed -i 's/^triangleMaterials \([0-9]*\) { 0 }/triangleMaterials \1 { 1 }/' constant/solidMesh
check solidMeshMaterialIndex solidMesh "'triangleMaterials'" femdemFoam

prep solidMeshTruncated bar
f=constant/solidMesh; head -c $(( $(stat -c %s $f) / 2 )) $f > $f.half && mv $f.half $f
check solidMeshTruncated solidMesh "FOAM FATAL IO ERROR" femdemFoam

prep meshCheckInverted bar
perl -pi -e "$invertFirst" constant/solidMesh
check meshCheckInverted solidMesh "triangle 0" femdemMeshCheck

prep meshCheckDuplicateTriangle bar
perl -pi -e "$duplicateFirst" constant/solidMesh
check meshCheckDuplicateTriangle solidMesh "triangles 0 and 1" femdemMeshCheck

# --- femdemMesh: system/femdemMeshDict (an existing constant/solidMesh stays)
prep femdemMeshMissingTargetSize bar
sed -i '/^targetSize/d' system/femdemMeshDict
check femdemMeshMissingTargetSize femdemMeshDict "'targetSize'" femdemMesh

prep femdemMeshNegativeTargetSize bar
setEntry system/femdemMeshDict targetSize -0.01
check femdemMeshNegativeTargetSize femdemMeshDict "targetSize" femdemMesh

prep femdemMeshMinAngle bar
setEntry system/femdemMeshDict minAngle 40
check femdemMeshMinAngle femdemMeshDict "minAngle" femdemMesh

prep femdemMeshUnknownType bar
sed -i 's/type rectangle/type rectangel/' system/femdemMeshDict
check femdemMeshUnknownType femdemMeshDict "rectangel" femdemMesh

prep femdemMeshMissingMaterial bar
sed -i 's/ material rock;//' system/femdemMeshDict
check femdemMeshMissingMaterial femdemMeshDict "'material'" femdemMesh

# --- gmshToFemdem
prep gmshMissingFile square
check gmshMissingFile "squar.msh" "Cannot open" gmshToFemdem squar.msh

prep gmshTruncated square
head -n 14 square.msh > cut.msh && mv cut.msh square.msh
check gmshTruncated "square.msh" "EndNodes" gmshToFemdem square.msh

prep gmshQuad square
sed -i 's/^6$/7/; s/^\$EndElements/7 3 2 2 1 1 2 3 4\n$EndElements/' square.msh
check gmshQuad "square.msh" "element 7" gmshToFemdem square.msh


# --- issue 17: restarts, empty or inconsistent dictionaries, sizes
prep restartMissingFemdemState boxRestart
rm 4e-06/uniform/femdemState
check restartMissingFemdemState "4e-06/uniform/femdemState" "missing" jwlIbFoam

prep femdemRestartMissingState barRun
sed -i 's/endTime 4e-6;/endTime 8e-6;/' system/controlDict
rm 4e-06/femdemState
check femdemRestartMissingState "4e-06/femdemState" "missing" femdemFoam

prep emptyFemdemProperties box
header femdemProperties > constant/femdemProperties
check emptyFemdemProperties femdemProperties "'materials'" jwlIbFoam

prep zeroByteFemdemProperties box
: > constant/femdemProperties
check zeroByteFemdemProperties femdemProperties "empty" jwlIbFoam

prep femdemMeshNoTriangles bar
sed -i 's/^solids/holes { all { type rectangle; min (-0.01 -0.01); max (0.04 0.03); } }\nsolids/' system/femdemMeshDict
check femdemMeshNoTriangles femdemMeshDict "'holes'" femdemMesh

zeroTriangles='s/^triangles\s+\d+\s*\(.*$/triangles 0 ();/; s/^triangleMaterials\s+\d+\s*\{.*$/triangleMaterials 0 ();/'
prep solidMeshNoTriangles barRun
perl -pi -e "$zeroTriangles" constant/solidMesh
check solidMeshNoTriangles solidMesh "'triangles'" femdemFoam

prep meshCheckNoTriangles barRun
perl -pi -e "$zeroTriangles" constant/solidMesh
check meshCheckNoTriangles solidMesh "'triangles'" femdemMeshCheck

for tol in -1 0 NaN; do
    prep "meshCheckMergeTol$tol" barRun
    check "meshCheckMergeTol$tol" "-mergeTol" "(0, 1)" femdemMeshCheck -mergeTol "$tol"
done

prep femdemWriteIntervalZero barRun
sed -i 's/writeInterval 2e-6;/writeInterval 0;/' system/controlDict
check femdemWriteIntervalZero controlDict "'writeInterval'" femdemFoam

prep writeIntervalZero sod
setEntry system/controlDict writeInterval 0
check writeIntervalZero controlDict "'writeInterval'" jwlIbFoam

prep writeIntervalNegative sod
setEntry system/controlDict writeInterval -0.01
check writeIntervalNegative controlDict "'writeInterval'" jwlIbFoam

prep femdemWriteIntervalNegative barRun
sed -i 's/writeInterval 2e-6;/writeInterval -2e-6;/' system/controlDict
check femdemWriteIntervalNegative controlDict "'writeInterval'" femdemFoam

prep femdemMeshTooManyTriangles bar
setEntry system/femdemMeshDict targetSize 1e-6
check femdemMeshTooManyTriangles femdemMeshDict "'targetSize'" femdemMesh

prep femdemPropertiesMaterialTwice bar
sed -i 's/^materials { rock {/materials { rock { E 1e9; } rock {/' constant/femdemProperties
check femdemPropertiesMaterialTwice femdemProperties "duplicate entry: rock" femdemFoam

prep thermoMaterialTwice sod
echo 'air { equationOfState idealGas; gamma 1.3; Cv 718; }' >> constant/thermophysicalProperties
check thermoMaterialTwice thermophysicalProperties "duplicate entry: air" jwlIbFoam

prep thermoMaterialsListedTwice tntCharged
sed -i 's/^materials (products air);/materials (air air);/' constant/thermophysicalProperties
check thermoMaterialsListedTwice thermophysicalProperties "'materials'" jwlIbFoam

prep solidMeshMaterialsListedTwice barRun
perl -pi -e 's/^materials\s+1\s*\(\s*rock\s*\)\s*;/materials 2 ( rock rock );/' constant/solidMesh
check solidMeshMaterialsListedTwice solidMesh "'materials'" femdemFoam

prep endTimeBeforeStartTime restart
setEntry system/controlDict endTime 0.01
check endTimeBeforeStartTime controlDict "'endTime'" jwlIbFoam

prep femdemEndTimeBeforeStartTime bar
sed -i 's/endTime 4e-6;/endTime -1;/' system/controlDict
check femdemEndTimeBeforeStartTime controlDict "'endTime'" femdemFoam

prep mpirunWithoutParallel sod
check mpirunWithoutParallel "-parallel" "MPI launcher" mpirun -np 2 jwlIbFoam

prep renumberBlockSizeZero barRun
check renumberBlockSizeZero "-blockSize" "0" femdemRenumber -blockSize 0

prep femdemMeshSelfCrossingPolygon bar
sed -i 's/type rectangle; min (0 0); max (0.03 0.02);/type polygon; points ((0 0) (0.03 0.02) (0.03 0) (0 0.02));/' system/femdemMeshDict
check femdemMeshSelfCrossingPolygon femdemMeshDict "'points'" femdemMesh

femdemCase negativeRampTime 's/type velocity; value (3 0.5);/type velocity; value (3 0.5); rampTime -1e-6;/' "'rampTime'"

prep gmshNoPhysicalGroups square
perl -0pi -e 's/\$PhysicalNames.*?\$EndPhysicalNames\n//s; s/^(\d+) (\d) 2 \d+ \d+ /$1 $2 2 0 1 /mg' square.msh
check gmshNoPhysicalGroups "square.msh" "physical surface" gmshToFemdem square.msh

prep gmshDuplicateNodeId square
sed -i 's/^4 0 1 0$/3 0 1 0/' square.msh
check gmshDuplicateNodeId "square.msh" "duplicate node id 3" gmshToFemdem square.msh

prep deltaTZero sod
setEntry system/controlDict deltaT 0
check deltaTZero "system/controlDict" "'deltaT'" jwlIbFoam

mkdir -p "$top/cases/with space"
prep casePathWithSpace bar
cd "$top" && rm -rf "cases/with space/bar" && mv cases/casePathWithSpace "cases/with space/bar"
mkdir -p cases/casePathWithSpace && cd "cases/with space/bar"
check casePathWithSpace "with space" "contains a space" femdemFoam

# Messages that point to the cause (issue 17, item 4): materials in the
# other order than the fields / setCharge; exactRiemann's bad states
prep thermoMaterialOrder tntCharged
sed -i 's/^materials .*/materials (air products);/' constant/thermophysicalProperties
check thermoMaterialOrder "thermophysicalProperties" "'materials'" jwlIbFoam

prep setChargeMaterialOrder tnt
sed -i 's/^materials .*/materials (air products);/' constant/thermophysicalProperties
check setChargeMaterialOrder "thermophysicalProperties" "'materials'" setCharge

# Three materials (water decoupling): more than three materials; a fill of
# an unknown material; three materials with the two-material crack gas
prep thermoFourMaterials tntCharged
sed -i 's/^materials .*/materials (products water air gas);/' constant/thermophysicalProperties
check thermoFourMaterials thermophysicalProperties "'materials'" jwlIbFoam

prep setChargeFillUnknownMaterial tnt
sed -i 's/^charges/fills ( circle { centre (0 0 0); radius 0.02; material mud; } );\ncharges/' system/setChargeDict
check setChargeFillUnknownMaterial setChargeDict "'material'" setCharge

prep threeMaterialsCrackGas box
sed -i 's/^materials .*/materials (products water air);/' constant/thermophysicalProperties
cat >> constant/thermophysicalProperties <<'D'
products { equationOfState JWL; explosive TNT; }
water { equationOfState stiffenedGas; gamma 4.4; pInf 6e8; }
D
for f in alpha.products alpha.water; do
    sed -e "s/object *rho;/object $f;/" -e 's/^dimensions.*/dimensions [0 0 0 0 0 0 0];/' \
        -e 's/^internalField.*/internalField uniform 1e-6;/' 0/rho > 0/$f
done
for m in products water air; do sed "s/object *rho;/object rho.$m;/" 0/rho > 0/rho.$m; done
echo 'crackGas { }' >> constant/immersedBodyProperties
check threeMaterialsCrackGas immersedBodyProperties "'crackGas'" jwlIbFoam

prep exactRiemannNegativeRho sod
sed -i 's/^left .*/left { material air; rho -1; u 0; p 1; }/' system/exactRiemannDict
check exactRiemannNegativeRho "exactRiemannDict" "'rho'" exactRiemann

prep exactRiemannNegativePressure sod
sed -i 's/^right .*/right { material air; rho 0.125; u 0; p -0.1; }/' system/exactRiemannDict
check exactRiemannNegativePressure "exactRiemannDict" "'p'" exactRiemann

prep exactRiemannNaNVelocity sod
sed -i 's/^right .*/right { material air; rho 0.125; u nan; p 0.1; }/' system/exactRiemannDict
check exactRiemannNaNVelocity "exactRiemannDict.right.u" "nan" exactRiemann

echo ">> $nCases cases, $nFailed failed"
[ $nFailed = 0 ]
