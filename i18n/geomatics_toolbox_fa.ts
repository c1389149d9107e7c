<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1">
    <context>
        <name>@default</name>
        <message>
            <source>terrain (hillshade)</source>
            <translation>ناهمواری (سایه‌روشن)</translation>
        </message>
        <message>
            <source>nodata</source>
            <translation>بدون داده</translation>
        </message>
        <message>
            <source>Legend</source>
            <translation>راهنما</translation>
        </message>
        <message>
            <source>Hillshade</source>
            <translation>سایه‌روشن</translation>
        </message>
        <message>
            <source>not used (outside / nodata)</source>
            <translation>به‌کارنرفته (بیرون / بدون داده)</translation>
        </message>
        <message>
            <source>Error DTM − check (m)</source>
            <translation>خطا = مدل − نقطهٔ چک (متر)</translation>
        </message>
        <message>
            <source>Residual map</source>
            <translation>نقشهٔ باقیمانده‌ها</translation>
        </message>
        <message>
            <source>check height (m)</source>
            <translation>ارتفاع نقطهٔ چک (متر)</translation>
        </message>
        <message>
            <source>error DTM − check (m)</source>
            <translation>خطا = مدل − نقطهٔ چک (متر)</translation>
        </message>
        <message>
            <source>zero error</source>
            <translation>خطای صفر</translation>
        </message>
        <message>
            <source>Error against height</source>
            <translation>خطا در برابر ارتفاع</translation>
        </message>
        <message>
            <source>no point</source>
            <translation>بدون نقطه</translation>
        </message>
        <message>
            <source>Class map</source>
            <translation>نقشهٔ کلاس‌ها</translation>
        </message>
        <message>
            <source>ASPRS class</source>
            <translation>کلاس ASPRS</translation>
        </message>
        <message>
            <source>Error map</source>
            <translation>نقشهٔ خطاها</translation>
        </message>
        <message>
            <source>Filter error</source>
            <translation>خطای فیلتر</translation>
        </message>
        <message>
            <source>Tile map</source>
            <translation>نقشهٔ کاشی‌ها</translation>
        </message>
        <message>
            <source>Tile status</source>
            <translation>وضعیت کاشی</translation>
        </message>
        <message>
            <source>Slope threshold θ (degrees)</source>
            <translation>آستانهٔ شیب θ (درجه)</translation>
        </message>
        <message>
            <source>Percent (%)</source>
            <translation>درصد (%)</translation>
        </message>
        <message>
            <source>best threshold</source>
            <translation>بهترین آستانه</translation>
        </message>
        <message>
            <source>Errors against the slope threshold</source>
            <translation>خطاها در برابر آستانهٔ شیب</translation>
        </message>
        <message>
            <source>fast</source>
            <translation>سریع</translation>
        </message>
        <message>
            <source>slow</source>
            <translation>کند</translation>
        </message>
        <message>
            <source>finished earlier</source>
            <translation>پیش‌تر تمام‌شده</translation>
        </message>
        <message>
            <source>failed</source>
            <translation>ناموفق</translation>
        </message>
        <message>
            <source>check-point RMS_T</source>
            <translation>RMS_T نقاط چک</translation>
        </message>
        <message>
            <source>map X</source>
            <translation>X نقشه</translation>
        </message>
        <message>
            <source>map Y</source>
            <translation>Y نقشه</translation>
        </message>
    </context>
    <context>
        <name>BuildingsAlgorithm</name>
        <message>
            <source>Building footprints with heights</source>
            <translation>ردپای ساختمان‌ها با ارتفاع</translation>
        </message>
        <message>
            <source>Roof planes found by region growing above the DTM, as footprints with height, area, volume, storeys and roof type.</source>
            <translation>صفحه‌های بام یافته‌شده با رشد ناحیه بالای مدل رقومی زمین، به‌صورت ردپا با ارتفاع، مساحت، حجم، طبقه‌ها و نوع بام.</translation>
        </message>
        <message>
            <source>buildings,footprints,roofs,lod1,extraction,height,volume,storeys,class 6,lidar</source>
            <translation>ساختمان‌ها,ردپا,بام‌ها,lod1,استخراج,ارتفاع,حجم,طبقه‌ها,کلاس ۶,لایدار</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Ground classes</source>
            <translation>کلاس‌های زمین</translation>
        </message>
        <message>
            <source>Minimum height above ground (m)</source>
            <translation>کمینهٔ ارتفاع از زمین (متر)</translation>
        </message>
        <message>
            <source>Maximum angle between roof normals (°)</source>
            <translation>بیشینهٔ زاویهٔ میان بردارهای عمود بام (درجه)</translation>
        </message>
        <message>
            <source>Minimum roof patch area (m²)</source>
            <translation>کمینهٔ مساحت وصلهٔ بام (مترمربع)</translation>
        </message>
        <message>
            <source>Minimum building area (m²)</source>
            <translation>کمینهٔ مساحت ساختمان (مترمربع)</translation>
        </message>
        <message>
            <source>Cell size (m)</source>
            <translation>اندازهٔ سلول (متر)</translation>
        </message>
        <message>
            <source>Building footprints</source>
            <translation>ردپای ساختمان‌ها</translation>
        </message>
        <message>
            <source>Classified cloud (class 6 = building)</source>
            <translation>ابر طبقه‌بندی‌شده (کلاس ۶ = ساختمان)</translation>
        </message>
        <message>
            <source>Ground in class 2 (run a ground filter first), in a projected CRS (metres).</source>
            <translation>زمین در کلاس 2 (نخست یک فیلتر زمین اجرا کنید)، در سامانهٔ مختصات تصویری (متر).</translation>
        </message>
        <message>
            <source>The specification gives 1.5–2 m.</source>
            <translation>مشخصات فنی 1.5–2 m را می‌دهد.</translation>
        </message>
        <message>
            <source>GeoPackage polygons with height, area, volume, storeys, roof type, ground and roof heights.</source>
            <translation>چندضلعی‌های GeoPackage با ارتفاع، مساحت، حجم، تعداد طبقه، نوع بام و ارتفاع زمین و بام.</translation>
        </message>
        <message>
            <source>Building footprints report</source>
            <translation>گزارش ردپای ساختمان‌ها</translation>
        </message>
        <message>
            <source>Buildings</source>
            <translation>ساختمان‌ها</translation>
        </message>
        <message>
            <source>Total footprint area (m²)</source>
            <translation>مساحت کل ردپاها (مترمربع)</translation>
        </message>
        <message>
            <source>Total volume (m³)</source>
            <translation>حجم کل (مترمکعب)</translation>
        </message>
        <message>
            <source>Extracts buildings from a ground-classified LAS/LAZ cloud: points above the ground TIN are fitted with local planes, and neighbours with agreeing normals grow into roof patches; trees are rejected because their points are not planar. Each footprint gets a roof model fitted to its roof points only (flat, shed, gabled, hipped or complex), so canopy over a roof does not raise it; heights, eave heights, area, volume and storeys follow from it. A deck whose surface runs on into the ground at both ends (a bridge) is not a building. Optional LOD1/LOD2 CityJSON and OBJ 3D models. Clouds in feet are converted: heights, areas and volumes are in metres, geometry in the data's CRS.</source>
            <translation>ساختمان‌ها را از ابر LAS/LAZ با زمین طبقه‌بندی‌شده استخراج می‌کند: به نقاط بالای TIN زمین صفحه‌های محلی برازش داده می‌شود و همسایه‌های با بردار نرمال هم‌سو به وصله‌های بام رشد می‌کنند؛ درختان رد می‌شوند چون نقاطشان صفحه‌ای نیست. هر ردپا یک مدل بام برازش‌یافته فقط بر نقاط بام خود می‌گیرد (تخت، یک‌طرفه، شیروانی، چهارشیب یا پیچیده)، پس تاج درخت روی بام آن را بالا نمی‌برد؛ ارتفاع، ارتفاع لبهٔ بام، مساحت، حجم و تعداد طبقه از آن به دست می‌آید. عرشه‌ای که سطحش در هر دو سر تا زمین ادامه دارد (پل) ساختمان نیست. مدل‌های سه‌بعدی اختیاری LOD1/LOD2 در CityJSON و OBJ. ابرهای فوتی تبدیل می‌شوند: ارتفاع، مساحت و حجم به متر، هندسه در سیستم مختصات داده.</translation>
        </message>
        <message>
            <source>Storeys = mean roof height above ground / this height (the specification gives 2.5–3.5 m).</source>
            <translation>تعداد طبقه = میانگین ارتفاع بام از زمین ÷ این ارتفاع (مشخصات 2.5–3.5 متر می‌دهد).</translation>
        </message>
        <message>
            <source>CityJSON 2.0: each building as an LOD1 block and, for rectangular footprints with a flat, shed, gabled or hipped roof, an LOD2 solid with roof, wall and ground surfaces.</source>
            <translation>CityJSON 2.0: هر ساختمان به‌صورت یک بلوک LOD1 و، برای ردپاهای مستطیلی با بام تخت، یک‌طرفه، شیروانی یا چهارشیب، یک حجم LOD2 با سطوح بام، دیوار و کف.</translation>
        </message>
        <message>
            <source>Storey height (m)</source>
            <translation>ارتفاع طبقه (متر)</translation>
        </message>
        <message>
            <source>3D city model (CityJSON, LOD1 and LOD2)</source>
            <translation>مدل سه‌بعدی شهر (CityJSON، LOD1 و LOD2)</translation>
        </message>
        <message>
            <source>3D model for viewers (OBJ)</source>
            <translation>مدل سه‌بعدی برای نمایشگرها (OBJ)</translation>
        </message>
        <message>
            <source>{} buildings; data units (horizontal / vertical): {}</source>
            <translation>{} ساختمان؛ یکای داده (افقی / قائم): {}</translation>
        </message>
    </context>
    <context>
        <name>CatalogAlgorithm</name>
        <message>
            <source>Process a LiDAR tile catalog</source>
            <translation>پردازش کاتالوگ کاشی‌های لایدار</translation>
        </message>
        <message>
            <source>Ground filter and DTM over a whole folder of LAS/LAZ tiles, in parallel, without seams.</source>
            <translation>فیلتر زمین و مدل رقومی زمین برای یک پوشهٔ کامل از کاشی‌های LAS/LAZ، به‌صورت موازی و بدون درز.</translation>
        </message>
        <message>
            <source>Keep the classes already in the files</source>
            <translation>نگه‌داشتن کلاس‌های موجود در فایل‌ها</translation>
        </message>
        <message>
            <source>LSQ surfaces, faithful (the paper)</source>
            <translation>سطوح کمترین مربعات، وفادار (مقاله)</translation>
        </message>
        <message>
            <source>LSQ surfaces, improved (ours)</source>
            <translation>سطوح کمترین مربعات، بهبودیافته (نسخهٔ ما)</translation>
        </message>
        <message>
            <source>Slope filter, exact (Vosselman 2000)</source>
            <translation>فیلتر شیب، دقیق (Vosselman 2000)</translation>
        </message>
        <message>
            <source>Slope filter, terrain-adaptive</source>
            <translation>فیلتر شیب، سازگار با عوارض زمین</translation>
        </message>
        <message>
            <source>IDW</source>
            <translation>IDW</translation>
        </message>
        <message>
            <source>Kriging</source>
            <translation>کریجینگ</translation>
        </message>
        <message>
            <source>TIN</source>
            <translation>TIN</translation>
        </message>
        <message>
            <source>Ground filter</source>
            <translation>فیلتر زمین</translation>
        </message>
        <message>
            <source>DTM method</source>
            <translation>روش مدل رقومی زمین</translation>
        </message>
        <message>
            <source>DTM cell size (m)</source>
            <translation>اندازهٔ سلول مدل زمین (متر)</translation>
        </message>
        <message>
            <source>Buffer around each tile (m)</source>
            <translation>حاشیهٔ پیرامون هر کاشی (متر)</translation>
        </message>
        <message>
            <source>Worker processes (0 = one per core)</source>
            <translation>پردازه‌های کارگر (0 = یکی برای هر هسته)</translation>
        </message>
        <message>
            <source>Dask scheduler address (empty = local)</source>
            <translation>نشانی زمان‌بند Dask (خالی = محلی)</translation>
        </message>
        <message>
            <source>Also write one Cloud-Optimized GeoTIFF</source>
            <translation>نوشتن یک GeoTIFF بهینه برای ابر نیز</translation>
        </message>
        <message>
            <source>Output folder</source>
            <translation>پوشهٔ خروجی</translation>
        </message>
        <message>
            <source>Tiles</source>
            <translation>کاشی‌ها</translation>
        </message>
        <message>
            <source>Failed tiles</source>
            <translation>کاشی‌های ناموفق</translation>
        </message>
        <message>
            <source>Points per second</source>
            <translation>نقطه در ثانیه</translation>
        </message>
        <message>
            <source>Tile {0} failed: {1}</source>
            <translation>کاشی {0} ناموفق بود: {1}</translation>
        </message>
        <message>
            <source>Ground filter (recommended)</source>
            <translation>فیلتر زمین (پیشنهادی)</translation>
        </message>
        <message>
            <source>Classifies ground and builds a DTM for every tile of a LiDAR project, each tile read with a buffer of its neighbours' points so that results have no seams. Tiles run in parallel on Dask, locally or on a cluster; a rerun skips finished tiles.</source>
            <translation>برای هر کاشی یک پروژهٔ LiDAR زمین را کلاس‌بندی و DTM می‌سازد؛ هر کاشی با حائلی از نقاط همسایه‌هایش خوانده می‌شود تا نتیجه درز نداشته باشد. کاشی‌ها به‌صورت موازی روی Dask، محلی یا روی خوشه، اجرا می‌شوند؛ اجرای دوباره کاشی‌های تمام‌شده را رد می‌کند.</translation>
        </message>
        <message>
            <source>The first choice keeps the classes already in the files.</source>
            <translation>گزینهٔ نخست کلاس‌های موجود در فایل‌ها را نگه می‌دارد.</translation>
        </message>
        <message>
            <source>e.g. tcp://host:8786.</source>
            <translation>مانند tcp://host:8786.</translation>
        </message>
        <message>
            <source>Must not hold the input tiles; receives the classified tiles, one DTM per tile and a VRT mosaic.</source>
            <translation>نباید کاشی‌های ورودی را در خود داشته باشد؛ کاشی‌های کلاس‌بندی‌شده، یک DTM برای هر کاشی و یک موزاییک VRT در آن نوشته می‌شود.</translation>
        </message>
        <message>
            <source>A map of the tiles by status, and time and points per second per worker.</source>
            <translation>نقشهٔ کاشی‌ها بر اساس وضعیت، و زمان و نقطه در ثانیه برای هر کارگر.</translation>
        </message>
        <message>
            <source>Tile catalog report</source>
            <translation>گزارش فهرست کاشی‌ها</translation>
        </message>
        <message>
            <source>0 processes whole tiles; a size (a multiple of the cell size) cuts the catalog into squares read from the tiles they overlap.</source>
            <translation>مقدار 0 کاشی‌ها را کامل پردازش می‌کند؛ یک اندازه (مضربی از اندازهٔ سلول) کاتالوگ را به مربع‌هایی تقسیم می‌کند که از کاشی‌های هم‌پوشان خوانده می‌شوند.</translation>
        </message>
        <message>
            <source>Chunk size (m, 0 = the tiles)</source>
            <translation>اندازهٔ تکه (متر، 0 = کاشی‌ها)</translation>
        </message>
        <message>
            <source>Must exceed the filter's reach (about 100 m for the recommended filter, 240 m for the improved LSQ, 120 m for the terrain-adaptive slope filter) and the DTM search distance.</source>
            <translation>باید از بُرد فیلتر (حدود 100 متر برای فیلتر پیشنهادی، 240 متر برای LSQ بهبودیافته و 120 متر برای فیلتر شیب سازگار با عوارض) و فاصلهٔ جست‌وجوی مدل رقومی زمین بیشتر باشد.</translation>
        </message>
        <message>
            <source>DTM mosaic (VRT)</source>
            <translation>موزاییک مدل رقومی زمین (VRT)</translation>
        </message>
        <message>
            <source>Tiles: LAS/LAZ files, folders or a .vpc</source>
            <translation>کاشی‌ها: فایل‌های LAS/LAZ، پوشه‌ها یا یک ‎.vpc</translation>
        </message>
        <message>
            <source>Tile {key}: finished by an earlier run, kept.</source>
            <translation>کاشی {key}: در اجرای پیشین تمام شده بود، نگه داشته شد.</translation>
        </message>
        <message>
            <source>Tile {key}: no point of its own, no DTM.</source>
            <translation>کاشی {key}: نقطه‌ای از خودش ندارد، بدون مدل رقومی زمین.</translation>
        </message>
        <message>
            <source>Tile {key} done: {points} points, {ground} ground, {seconds:.1f} s.</source>
            <translation>کاشی {key} تمام شد: {points} نقطه، {ground} زمینی، {seconds:.1f} ثانیه.</translation>
        </message>
        <message>
            <source>Cancelled by the user. {n} finished tile(s) are kept in {folder}: run again with the same settings to resume; unfinished tiles left nothing.</source>
            <translation>کاربر لغو کرد. {n} کاشیِ تمام‌شده در {folder} نگه داشته شد: برای ادامه با همان تنظیمات دوباره اجرا کنید؛ کاشی‌های ناتمام چیزی به جا نگذاشتند.</translation>
        </message>
        <message>
            <source>Ground filter (progressive TIN densification)</source>
            <translation>فیلتر زمین (متراکم‌سازی تدریجی TIN)</translation>
        </message>
        <message>
            <source>Off: a damaged or truncated tile stops the run before anything is written, naming every such tile. On: those tiles are left out (named in the log) and their neighbours get no buffer points from them.</source>
            <translation>خاموش: هر کاشی آسیب‌دیده یا ناقص پیش از نوشتن هر چیزی اجرا را متوقف می‌کند و همهٔ این کاشی‌ها را نام می‌برد. روشن: آن کاشی‌ها کنار گذاشته می‌شوند (در گزارش کار نام برده می‌شوند) و همسایه‌هایشان از آن‌ها نقطهٔ حاشیه نمی‌گیرند.</translation>
        </message>
        <message>
            <source>Skip unreadable tiles</source>
            <translation>رد شدن از کاشی‌های ناخوانا</translation>
        </message>
        <message>
            <source>Tile {path} skipped: {reason}</source>
            <translation>از کاشی {path} گذشته شد: {reason}</translation>
        </message>
        <message>
            <source>All tiles must share one CRS. Tiles without points are left out; tiles without ground within reach (a lake, the sea) get a nodata DTM. Both are named in the log and the report.</source>
            <translation>همهٔ کاشی‌ها باید یک سامانهٔ مختصات داشته باشند. کاشی‌های بدون نقطه کنار گذاشته می‌شوند؛ کاشی‌هایی که زمینی در دسترس ندارند (دریاچه، دریا) مدل رقومی زمین بدون داده می‌گیرند. هر دو در گزارش کار و گزارش نام برده می‌شوند.</translation>
        </message>
        <message>
            <source>Cells are nodata where a DTM of all the tiles as one file would leave them empty: farther than five mean ground spacings from ground (TIN: triangles with an edge over twice that), derived from the whole catalog once every tile is done.</source>
            <translation>سلول‌ها در جایی بدون داده‌اند که مدل رقومی زمینِ همهٔ کاشی‌ها به‌صورت یک فایل آن‌ها را خالی می‌گذارد: دورتر از پنج برابر میانگین فاصلهٔ نقاط زمین از زمین (در TIN: مثلث‌هایی که یک ضلعشان بیش از دو برابر آن است)؛ این فاصله پس از پایان همهٔ کاشی‌ها از کل کاتالوگ به دست می‌آید.</translation>
        </message>
        <message>
            <source>Terminated. {n} finished tile(s) are kept in {folder}: run again with the same settings to resume; unfinished tiles left nothing.</source>
            <translation>اجرا متوقف شد. {n} کاشیِ تمام‌شده در {folder} نگه داشته شد: برای ادامه با همان تنظیمات دوباره اجرا کنید؛ کاشی‌های ناتمام چیزی به جا نگذاشتند.</translation>
        </message>
        <message>
            <source>{n} tile(s) classified again at the canopy scale of the whole catalog: {keys}.</source>
            <translation>{n} کاشی دوباره با مقیاس تاج‌پوشش کل کاتالوگ طبقه‌بندی شد: {keys}.</translation>
        </message>
        <message>
            <source>A kept tile whose canopy scale differs from the whole catalog's is classified again by the resume.</source>
            <translation>کاشی نگه‌داشته‌ای که مقیاس تاج‌پوشش آن با مقیاس کل کاتالوگ فرق دارد، هنگام ادامه دادن دوباره طبقه‌بندی می‌شود.</translation>
        </message>
    </context>
    <context>
        <name>CheckPointInputs</name>
        <message>
            <source>Check points (point layer)</source>
            <translation>نقاط چک (لایهٔ نقطه‌ای)</translation>
        </message>
        <message>
            <source>Height field (empty = geometry Z)</source>
            <translation>فیلد ارتفاع (خالی = Z هندسه)</translation>
        </message>
        <message>
            <source>Id field</source>
            <translation>فیلد شناسه</translation>
        </message>
        <message>
            <source>CRS of the check point file (default: DTM CRS)</source>
            <translation>سیستم مختصات پروندهٔ نقاط چک (پیش‌فرض: سیستم مختصات DTM)</translation>
        </message>
        <message>
            <source>Reproject check points to the DTM CRS</source>
            <translation>بازتصویر نقاط چک به سیستم مختصات DTM</translation>
        </message>
        <message>
            <source>Sampling</source>
            <translation>روش نمونه‌برداری</translation>
        </message>
        <message>
            <source>Bilinear</source>
            <translation>دوخطی</translation>
        </message>
        <message>
            <source>Nearest cell</source>
            <translation>نزدیک‌ترین سلول</translation>
        </message>
        <message>
            <source>Give the check points as a point layer (CHECKPOINTS) or a file (CHECKPOINTS_CSV).</source>
            <translation>نقاط چک را به‌صورت لایهٔ نقطه‌ای (CHECKPOINTS) یا پرونده (CHECKPOINTS_CSV) بدهید.</translation>
        </message>
        <message>
            <source>Give the check points either as a layer or as a file, not both.</source>
            <translation>نقاط چک را یا به‌صورت لایه یا به‌صورت پرونده بدهید، نه هر دو.</translation>
        </message>
        <message>
            <source>The check point layer has no Z coordinate; choose the height field (Z_FIELD).</source>
            <translation>لایهٔ نقاط چک مختصات Z ندارد؛ فیلد ارتفاع (Z_FIELD) را انتخاب کنید.</translation>
        </message>
        <message>
            <source>The check point layer has no points.</source>
            <translation>لایهٔ نقاط چک هیچ نقطه‌ای ندارد.</translation>
        </message>
        <message>
            <source>check point layer</source>
            <translation>لایهٔ نقاط چک</translation>
        </message>
        <message>
            <source>check point file</source>
            <translation>پروندهٔ نقاط چک</translation>
        </message>
        <message>
            <source>The {} is in {} but the DTM is in {}. Reproject the check points first or tick 'Reproject check points to the DTM CRS' (REPROJECT=true; x, y only, heights are not converted). No output was written.</source>
            <translation>{} در سیستم مختصات {} است ولی مدل رقومی زمین در {} است. ابتدا نقاط چک را بازتصویر کنید یا گزینهٔ 'بازتصویر نقاط چک به سیستم مختصات DTM' را فعال کنید (REPROJECT=true؛ فقط x و y، ارتفاع‌ها تبدیل نمی‌شوند). هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Check points reprojected from {} to {}</source>
            <translation>نقاط چک از {} به {} بازتصویر شدند</translation>
        </message>
        <message>
            <source>Check points assumed to be in the DTM's CRS.</source>
            <translation>فرض شد نقاط چک در سیستم مختصات مدل رقومی زمین هستند.</translation>
        </message>
    </context>
    <context>
        <name>ClassifyAlgorithm</name>
        <message>
            <source>Classify point cloud (ASPRS classes)</source>
            <translation>طبقه‌بندی ابر نقاط (کلاس‌های ASPRS)</translation>
        </message>
        <message>
            <source>Ground, low/medium/high vegetation, buildings and low noise in one run; water and the other attributes kept.</source>
            <translation>زمین، پوشش گیاهی کوتاه/متوسط/بلند، ساختمان‌ها و نویز پایین در یک اجرا؛ آب و دیگر ویژگی‌ها حفظ می‌شوند.</translation>
        </message>
        <message>
            <source>lidar,las,laz,classification,asprs,ground,vegetation,building,noise,water,height above ground,normalize</source>
            <translation>لایدار,las,laz,طبقه‌بندی,asprs,زمین,پوشش گیاهی,ساختمان,نویز,آب,ارتفاع از زمین,نرمال‌سازی</translation>
        </message>
        <message>
            <source>Writes standard ASPRS classes into a copy of a LAS/LAZ cloud: 2 ground (the recommended ground filter, or the input's class 2 kept), 3/4/5 low/medium/high vegetation by height above a TIN of the ground, 6 building (roof planes, bridges refused), 7 low noise; water (9) and noise (18) are kept. Every other attribute, the VLRs and the CRS are copied unchanged. Heights are in metres also for clouds in feet (converted).</source>
            <translation>کلاس‌های استاندارد ASPRS را در رونوشتی از ابر LAS/LAZ می‌نویسد: ‏2 زمینی (فیلتر زمین پیشنهادی، یا حفظ کلاس 2 ورودی)، ‏3/4/5 پوشش گیاهی کوتاه/متوسط/بلند بر پایهٔ ارتفاع از TIN زمین، ‏6 ساختمان (صفحه‌های بام، پل‌ها رد می‌شوند)، ‏7 نویز پایین؛ آب (9) و نویز (18) حفظ می‌شوند. همهٔ ویژگی‌های دیگر، VLRها و سیستم مختصات بی‌تغییر کپی می‌شوند. ارتفاع‌ها برای ابرهای فوتی نیز به متر هستند (تبدیل می‌شوند).</translation>
        </message>
        <message>
            <source>A .las or .laz file in a projected CRS.</source>
            <translation>یک فایل .las یا .laz در سیستم مختصات تصویرشده.</translation>
        </message>
        <message>
            <source>Keep the input's class 2 when it was already filtered.</source>
            <translation>اگر ورودی پیش‌تر فیلتر شده است، کلاس 2 آن را حفظ کنید.</translation>
        </message>
        <message>
            <source>Default 0.5 m and 1.5 m: the IGN LiDAR HD vegetation classes.</source>
            <translation>پیش‌فرض 0.5 متر و 1.5 متر: کلاس‌های پوشش گیاهی IGN LiDAR HD.</translation>
        </message>
        <message>
            <source>The specification gives 1.5–2 m.</source>
            <translation>مشخصات فنی 1.5–2 m را می‌دهد.</translation>
        </message>
        <message>
            <source>Classes 8 and 10–255 (rail, road, wires, bridge decks, vendor classes) keep their class.</source>
            <translation>کلاس‌های 8 و 10–255 (ریل، جاده، سیم‌ها، عرشهٔ پل‌ها، کلاس‌های تأمین‌کننده) کلاس خود را حفظ می‌کنند.</translation>
        </message>
        <message>
            <source>A float extra dimension HeightAboveGround in the cloud's vertical unit (as PDAL's filters.hag_delaunay).</source>
            <translation>بُعد اضافی اعشاری HeightAboveGround با یکای قائم ابر (مانند filters.hag_delaunay در PDAL).</translation>
        </message>
        <message>
            <source>&lt;p&gt;References: ASPRS LAS 1.4 R15, standard point classes; Kostrikov, S. et al. (2020), ISPRS IJGI 9(11), 650; IGN (2023), LiDAR HD classes.&lt;/p&gt;</source>
            <translation>&lt;p&gt;منابع: ASPRS LAS 1.4 R15، کلاس‌های استاندارد نقاط؛ Kostrikov, S. و همکاران (2020)، ISPRS IJGI 9(11)، 650؛ IGN (2023)، کلاس‌های LiDAR HD.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Ground</source>
            <translation>زمین</translation>
        </message>
        <message>
            <source>Recommended ground filter</source>
            <translation>فیلتر زمین پیشنهادی</translation>
        </message>
        <message>
            <source>Keep the input's class 2</source>
            <translation>حفظ کلاس 2 ورودی</translation>
        </message>
        <message>
            <source>Low vegetation up to (m)</source>
            <translation>پوشش گیاهی کوتاه تا (متر)</translation>
        </message>
        <message>
            <source>Medium vegetation up to (m)</source>
            <translation>پوشش گیاهی متوسط تا (متر)</translation>
        </message>
        <message>
            <source>Find buildings (class 6)</source>
            <translation>یافتن ساختمان‌ها (کلاس 6)</translation>
        </message>
        <message>
            <source>Minimum building height above ground (m)</source>
            <translation>کمینهٔ ارتفاع ساختمان از زمین (متر)</translation>
        </message>
        <message>
            <source>Keep other input classes</source>
            <translation>حفظ کلاس‌های دیگر ورودی</translation>
        </message>
        <message>
            <source>Add height above ground</source>
            <translation>افزودن ارتفاع از زمین</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>Classification report</source>
            <translation>گزارش طبقه‌بندی</translation>
        </message>
        <message>
            <source>Points read</source>
            <translation>نقاط خوانده‌شده</translation>
        </message>
        <message>
            <source>Ground points (class 2)</source>
            <translation>نقاط زمینی (کلاس 2)</translation>
        </message>
        <message>
            <source>Vegetation points (classes 3-5)</source>
            <translation>نقاط پوشش گیاهی (کلاس‌های 3-5)</translation>
        </message>
        <message>
            <source>Building points (class 6)</source>
            <translation>نقاط ساختمان (کلاس 6)</translation>
        </message>
        <message>
            <source>Low noise points (class 7)</source>
            <translation>نقاط نویز پایین (کلاس 7)</translation>
        </message>
        <message>
            <source>Buildings</source>
            <translation>ساختمان‌ها</translation>
        </message>
        <message>
            <source>{} points: {} ground, {} vegetation, {} building, {} low noise; {} buildings</source>
            <translation>{} نقطه: {} زمینی، {} پوشش گیاهی، {} ساختمان، {} نویز پایین؛ {} ساختمان</translation>
        </message>
    </context>
    <context>
        <name>DsmAlgorithm</name>
        <message>
            <source>DSM and nDSM / canopy height model</source>
            <translation>مدل رقومی سطح (DSM) و nDSM / مدل ارتفاع تاج پوشش گیاهی</translation>
        </message>
        <message>
            <source>dsm,ndsm,chm,canopy height,surface model,first returns,lidar,raster</source>
            <translation>dsm,ndsm,chm,ارتفاع تاج پوشش,مدل سطح,بازگشت‌های اول,لایدار,رستر</translation>
        </message>
        <message>
            <source>Excluded classes</source>
            <translation>کلاس‌های کنارگذاشته</translation>
        </message>
        <message>
            <source>First returns only</source>
            <translation>فقط بازگشت‌های اول</translation>
        </message>
        <message>
            <source>Fill empty cells up to (m)</source>
            <translation>پر کردن سلول‌های خالی تا فاصلهٔ (متر)</translation>
        </message>
        <message>
            <source>DTM (for the nDSM; its grid is used)</source>
            <translation>مدل رقومی زمین DTM (برای nDSM؛ شبکهٔ آن به کار می‌رود)</translation>
        </message>
        <message>
            <source>Clamp negative nDSM heights to 0</source>
            <translation>برابر 0 قرار دادن ارتفاع‌های منفی nDSM</translation>
        </message>
        <message>
            <source>DSM</source>
            <translation>مدل رقومی سطح (DSM)</translation>
        </message>
        <message>
            <source>nDSM / canopy height model</source>
            <translation>nDSM / مدل ارتفاع تاج پوشش گیاهی</translation>
        </message>
        <message>
            <source>The point cloud CRS ({}) differs from the DTM CRS ({}); give a DTM in the point cloud's CRS. No output was written.</source>
            <translation>سیستم مختصات ابر نقاط ({}) با سیستم مختصات مدل رقومی زمین ({}) متفاوت است؛ مدل رقومی زمینی در سیستم مختصات ابر نقاط بدهید. هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>The nDSM needs a DTM: give the DTM parameter (e.g. the output of the IDW DTM algorithm). No output was written.</source>
            <translation>nDSM به مدل رقومی زمین نیاز دارد: پارامتر DTM را بدهید (مثلاً خروجی الگوریتم مدل رقومی زمین به روش IDW). هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>DSM report</source>
            <translation>گزارش مدل رقومی سطح (DSM)</translation>
        </message>
        <message>
            <source>Builds a digital surface model from a LAS/LAZ file: each cell takes the highest return falling in it. With a DTM it also writes the normalised DSM (canopy height model in forests) = DSM − DTM on the DTM's grid.</source>
            <translation>مدل رقومی سطح را از یک فایل LAS/LAZ می‌سازد: هر سلول بلندترین بازگشتِ درون خود را می‌گیرد. با داشتن DTM، مدل سطح نرمال‌شده (مدل ارتفاع تاج پوشش در جنگل) = DSM − DTM را هم روی شبکهٔ DTM می‌نویسد.</translation>
        </message>
        <message>
            <source>By default low and high noise.</source>
            <translation>به‌طور پیش‌فرض: نوفه‌های پایین و بالا.</translation>
        </message>
        <message>
            <source>The usual canopy surface.</source>
            <translation>سطح معمول تاج پوشش.</translation>
        </message>
        <message>
            <source>Empty cells take the nearest value within this distance; 0 = leave them nodata.</source>
            <translation>سلول‌های خالی نزدیک‌ترین مقدار درون این فاصله را می‌گیرند؛ 0 = بدون داده می‌مانند.</translation>
        </message>
        <message>
            <source>Its grid and CRS replace the cell size, extent and CRS, so that DSM and DTM align cell for cell.</source>
            <translation>شبکه و سامانهٔ مختصات آن جایگزین اندازهٔ سلول، گستره و سامانهٔ مختصات می‌شود تا DSM و DTM سلول به سلول منطبق باشند.</translation>
        </message>
        <message>
            <source>Needs a DTM.</source>
            <translation>به DTM نیاز دارد.</translation>
        </message>
        <message>
            <source>DSM cells with a value</source>
            <translation>سلول‌های دارای مقدار در DSM</translation>
        </message>
        <message>
            <source>Maximum nDSM height</source>
            <translation>بیشینهٔ ارتفاع nDSM</translation>
        </message>
    </context>
    <context>
        <name>DtmAccuracyAlgorithm</name>
        <message>
            <source>DTM accuracy against check points</source>
            <translation>دقت مدل رقومی زمین نسبت به نقاط چک</translation>
        </message>
        <message>
            <source>dtm,dem,accuracy,rmse,check points,gnss,nmad,asprs,vertical accuracy,validation</source>
            <translation>dtm,dem,دقت,rmse,نقاط چک,gnss,nmad,asprs,دقت ارتفاعی,اعتبارسنجی</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>مدل رقومی زمین (DTM)</translation>
        </message>
        <message>
            <source>Band</source>
            <translation>باند</translation>
        </message>
        <message>
            <source>Check point file (CSV/TXT)</source>
            <translation>پروندهٔ نقاط چک (CSV/TXT)</translation>
        </message>
        <message>
            <source>Residuals</source>
            <translation>باقی‌مانده‌ها</translation>
        </message>
        <message>
            <source>Choose a DTM raster.</source>
            <translation>یک رستر مدل رقومی زمین انتخاب کنید.</translation>
        </message>
        <message>
            <source>N = {}, RMSE = {:.4f} m, ME = {:.4f} m, r = {:.5f}; {} outside, {} on nodata</source>
            <translation>⁦N = {}⁩، ⁦RMSE = {:.4f}⁩ متر، ⁦ME = {:.4f}⁩ متر، ⁦r = {:.5f}⁩؛ {} بیرون از مدل، {} روی nodata</translation>
        </message>
        <message>
            <source>Compares a DTM with independent check points (e.g. GNSS heights) and summarises the errors e = z&lt;sub&gt;DTM&lt;/sub&gt; − z&lt;sub&gt;check&lt;/sub&gt; as bias, mean absolute error, RMSE, NMAD, Pearson r and the vertical accuracy at 95 % = 1.96·RMSE (ASPRS 2014). Check points outside the DTM or on nodata are counted and excluded, never read as 0.</source>
            <translation>DTM را با نقاط چک مستقل (مانند ارتفاع‌های GNSS) مقایسه می‌کند و خطاهای e = z&lt;sub&gt;DTM&lt;/sub&gt; − z&lt;sub&gt;check&lt;/sub&gt; را به‌صورت اریبی، میانگین خطای مطلق، RMSE، NMAD، ضریب پیرسون r و دقت ارتفاعی در سطح 95 % = 1.96·RMSE ‏(ASPRS 2014) خلاصه می‌کند. نقاط چکِ بیرون از DTM یا روی سلول‌های بدون داده شمرده و کنار گذاشته می‌شوند و هرگز 0 خوانده نمی‌شوند.</translation>
        </message>
        <message>
            <source>Give the layer or the file.</source>
            <translation>لایه یا فایل را بدهید.</translation>
        </message>
        <message>
            <source>A header x/easting, y/northing, z/height (and id/name), or columns id x y z without a header.</source>
            <translation>سرستون‌های x/easting، y/northing، z/height (و id/name)، یا ستون‌های id x y z بدون سرستون.</translation>
        </message>
        <message>
            <source>x and y only: heights are not converted between vertical datums. Without it, check points in another CRS are an error.</source>
            <translation>فقط x و y: ارتفاع‌ها میان مبناهای ارتفاعی تبدیل نمی‌شوند. بدون این گزینه، نقاط چک در سامانهٔ مختصات دیگر خطا به شمار می‌آیند.</translation>
        </message>
        <message>
            <source>Point layer with the error and status of each check point, styled by error.</source>
            <translation>لایهٔ نقطه‌ای با خطا و وضعیت هر نقطهٔ چک، نمادپردازی‌شده بر اساس خطا.</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>گزارش دقت مدل رقومی زمین</translation>
        </message>
        <message>
            <source>Only {n} check points were compared with the DTM: ASPRS (2014) asks for at least {minimum} check points before a vertical accuracy is stated, so these statistics are indicative only. Add check points (at least {minimum}) to state an accuracy.</source>
            <translation>فقط {n} نقطهٔ چک با مدل رقومی زمین (DTM) مقایسه شد: ASPRS (2014) پیش از اعلام دقت ارتفاعی دست‌کم {minimum} نقطهٔ چک می‌خواهد، پس این آماره‌ها فقط جنبهٔ راهنما دارند. برای اعلام دقت، نقاط چک بیشتری (دست‌کم {minimum}) اضافه کنید.</translation>
        </message>
    </context>
    <context>
        <name>ElevationChangeAlgorithm</name>
        <message>
            <source>Elevation change between two epochs (cut / fill)</source>
            <translation>تغییر ارتفاع میان دو دوره (خاک‌برداری / خاک‌ریزی)</translation>
        </message>
        <message>
            <source>Difference of two surveys with a 95 % level of detection, and cut and fill polygons with volumes.</source>
            <translation>تفاضل دو برداشت با حد آشکارسازی ۹۵ درصد، و چندضلعی‌های خاک‌برداری و خاک‌ریزی با حجم آن‌ها.</translation>
        </message>
        <message>
            <source>change,difference,dod,cut,fill,volume,epochs,lod,monitoring,lidar,dtm,dsm</source>
            <translation>تغییر,تفاضل,dod,خاک‌برداری,خاک‌ریزی,حجم,دوره‌ها,حد آشکارسازی,پایش,لایدار,dtm,dsm</translation>
        </message>
        <message>
            <source>Before (raster or point cloud)</source>
            <translation>پیش از (رستر یا ابر نقاط)</translation>
        </message>
        <message>
            <source>After (raster or point cloud)</source>
            <translation>پس از (رستر یا ابر نقاط)</translation>
        </message>
        <message>
            <source>Vertical accuracy before σ₁ (m)</source>
            <translation>دقت ارتفاعی پیش از σ₁ (متر)</translation>
        </message>
        <message>
            <source>Vertical accuracy after σ₂ (m)</source>
            <translation>دقت ارتفاعی پس از σ₂ (متر)</translation>
        </message>
        <message>
            <source>Classes used (clouds)</source>
            <translation>کلاس‌های به‌کاررفته (برای ابرها)</translation>
        </message>
        <message>
            <source>Cell size (m, clouds)</source>
            <translation>اندازهٔ سلول (متر، برای ابرها)</translation>
        </message>
        <message>
            <source>Minimum region area (m², 0 = 8 cells)</source>
            <translation>کمینهٔ مساحت ناحیه (مترمربع، 0 = هشت سلول)</translation>
        </message>
        <message>
            <source>Difference</source>
            <translation>تفاضل</translation>
        </message>
        <message>
            <source>Change polygons</source>
            <translation>چندضلعی‌های تغییر</translation>
        </message>
        <message>
            <source>Subtracts an earlier surface from a later one (two rasters on one grid, or two LAS/LAZ clouds gridded by TIN) and keeps the change beyond the level of detection LoD95 = 1.96·√(σ₁² + σ₂²). Significant cells form cut and fill polygons with area, mean change and volume.</source>
            <translation>سطح پیشین را از سطح پسین کم می‌کند (دو رستر روی یک شبکه، یا دو ابر LAS/LAZ که با TIN شبکه‌بندی شده‌اند) و تغییرِ فراتر از حد آشکارسازی LoD95 = 1.96·√(σ₁² + σ₂²) را نگه می‌دارد. سلول‌های معنادار چندضلعی‌های خاک‌برداری و خاک‌ریزی با مساحت، میانگین تغییر و حجم می‌سازند.</translation>
        </message>
        <message>
            <source>A GeoTIFF, or a LAS/LAZ cloud in the same CRS as the other epoch.</source>
            <translation>یک GeoTIFF، یا یک ابر LAS/LAZ در همان سامانهٔ مختصاتِ دورهٔ دیگر.</translation>
        </message>
        <message>
            <source>The vertical accuracy of the epoch, e.g. the RMSE of the DTM accuracy tool.</source>
            <translation>دقت ارتفاعی دوره، مانند RMSE ابزار دقت DTM.</translation>
        </message>
        <message>
            <source>Smaller regions are dropped: noise alone exceeds the LoD in 5 % of cells.</source>
            <translation>ناحیه‌های کوچک‌تر حذف می‌شوند: نوفه به‌تنهایی در 5 % سلول‌ها از حد آشکارسازی فراتر می‌رود.</translation>
        </message>
        <message>
            <source>GeoTIFF of after − before (m).</source>
            <translation>فایل GeoTIFF پسین − پیشین (m).</translation>
        </message>
        <message>
            <source>GeoPackage with kind (cut / fill), area, mean change and volume.</source>
            <translation>فایل GeoPackage با نوع (خاک‌برداری / خاک‌ریزی)، مساحت، میانگین تغییر و حجم.</translation>
        </message>
        <message>
            <source>Elevation change report</source>
            <translation>گزارش تغییر ارتفاع</translation>
        </message>
        <message>
            <source>The residual layer of a DTM accuracy run on this epoch: σ becomes the RMSE of its residuals (status used) and the typed σ is ignored.</source>
            <translation>لایهٔ باقیمانده‌های اجرای ابزار دقت DTM روی این دوره: σ برابر RMSE باقیمانده‌های آن (وضعیت used) می‌شود و σ واردشده نادیده گرفته می‌شود.</translation>
        </message>
        <message>
            <source>A raster on another grid in the same CRS is resampled (bilinear) onto the first one's grid.</source>
            <translation>رستری با شبکه‌ای دیگر در همان سیستم مختصات (دوخطی) روی شبکهٔ رستر اول بازنمونه‌برداری می‌شود.</translation>
        </message>
        <message>
            <source>σ₁ from a DTM accuracy run (residual layer, optional)</source>
            <translation>σ₁ از اجرای ابزار دقت DTM (لایهٔ باقیمانده‌ها، اختیاری)</translation>
        </message>
        <message>
            <source>σ₂ from a DTM accuracy run (residual layer, optional)</source>
            <translation>σ₂ از اجرای ابزار دقت DTM (لایهٔ باقیمانده‌ها، اختیاری)</translation>
        </message>
        <message>
            <source>The second raster ({0} × {1} cells of {2:g} m) is resampled (bilinear) onto the first one's grid ({3} × {4} cells of {5:g} m).</source>
            <translation>رستر دوم ({0} × {1} سلول {2:g} متری) به روش دوخطی روی شبکهٔ رستر اول ({3} × {4} سلول {5:g} متری) بازنمونه‌برداری می‌شود.</translation>
        </message>
        <message>
            <source>{0} = {1:.4f} m: RMSE of {2} check-point residuals of {3}</source>
            <translation>{0} = {1:.4f} متر: RMSE {2} باقیماندهٔ نقاط چک در {3}</translation>
        </message>
        <message>
            <source>A raster layer of the project or a raster file; give each epoch once, as a file or as a raster layer.</source>
            <translation>یک لایهٔ رستری پروژه یا یک فایل رستری؛ هر دوره را یک بار بدهید، به‌صورت فایل یا لایهٔ رستری.</translation>
        </message>
        <message>
            <source>Before as a raster layer (instead of a file)</source>
            <translation>قبل، به‌صورت لایهٔ رستری (به‌جای فایل)</translation>
        </message>
        <message>
            <source>After as a raster layer (instead of a file)</source>
            <translation>بعد، به‌صورت لایهٔ رستری (به‌جای فایل)</translation>
        </message>
        <message>
            <source>Level of detection LoD95 (m)</source>
            <translation>حد آشکارسازی LoD95 (متر)</translation>
        </message>
        <message>
            <source>Fill volume above the LoD (m³)</source>
            <translation>حجم خاک‌ریزی بالاتر از حد آشکارسازی (مترمکعب)</translation>
        </message>
        <message>
            <source>Cut volume above the LoD (m³)</source>
            <translation>حجم خاک‌برداری بالاتر از حد آشکارسازی (مترمکعب)</translation>
        </message>
        <message>
            <source>Change regions</source>
            <translation>نواحی تغییر</translation>
        </message>
        <message>
            <source>{0} has no CRS: it is taken to be in the CRS of {1} ({2}); check that it is.</source>
            <translation>{0} سیستم مختصات ندارد: در سیستم مختصات {1} ({2}) فرض می‌شود؛ درستی آن را بررسی کنید.</translation>
        </message>
    </context>
    <context>
        <name>GcpAccuracyReportAlgorithm</name>
        <message>
            <source>GCP accuracy report</source>
            <translation>گزارش دقت نقاط کنترل زمینی</translation>
        </message>
        <message>
            <source>georeference,gcp,ground control points,rms,residuals,accuracy,check points,leave-one-out,polynomial,georeferencer</source>
            <translation>زمین‌مرجع‌سازی,gcp,نقاط کنترل زمینی,rms,باقی‌مانده‌ها,دقت,نقاط چک,حذف‌یکی,چندجمله‌ای,georeferencer</translation>
        </message>
        <message>
            <source>Image width (px) if no image is given</source>
            <translation>عرض تصویر (پیکسل) اگر تصویری داده نشود</translation>
        </message>
        <message>
            <source>Image height (px) if no image is given</source>
            <translation>ارتفاع تصویر (پیکسل) اگر تصویری داده نشود</translation>
        </message>
        <message>
            <source>Residuals table</source>
            <translation>جدول باقی‌مانده‌ها</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>پرونده‌های CSV (*.csv)</translation>
        </message>
        <message>
            <source>JSON files (*.json)</source>
            <translation>پرونده‌های JSON (*.json)</translation>
        </message>
        <message>
            <source>Judges a set of ground control points without warping: every transformation side by side by the paper's criteria on check points and leave-one-out residuals. It recommends one transformation, says why, and suggests points to drop.</source>
            <translation>مجموعه‌ای از نقاط کنترل زمینی را بدون تصحیح تصویر ارزیابی می‌کند: همهٔ تبدیل‌ها کنار هم بر پایهٔ معیارهای مقاله روی نقاط چک و باقیمانده‌های حذف‌یکی. یک تبدیل را توصیه می‌کند، دلیلش را می‌گوید و نقاطی را برای حذف پیشنهاد می‌دهد.</translation>
        </message>
        <message>
            <source>Gives the image size; without it give the image width and height, or the GCP centroid is used.</source>
            <translation>اندازهٔ تصویر را می‌دهد؛ بدون آن عرض و ارتفاع تصویر را بدهید، وگرنه مرکز نقاط کنترل به کار می‌رود.</translation>
        </message>
        <message>
            <source>One row per point with its residuals in map units and pixels.</source>
            <translation>یک سطر برای هر نقطه با باقیمانده‌هایش بر حسب واحد نقشه و پیکسل.</translation>
        </message>
        <message>
            <source>GCP accuracy report as JSON</source>
            <translation>گزارش دقت نقاط کنترل زمینی در قالب JSON</translation>
        </message>
        <message>
            <source>RMS_T of order {} (map units)</source>
            <translation>RMS_T مرتبهٔ {} (واحد نقشه)</translation>
        </message>
        <message>
            <source>Leave-one-out RMS_T of order {}</source>
            <translation>RMS_T به روش یکی‌کنارگذاری برای مرتبهٔ {}</translation>
        </message>
        <message>
            <source>Order {order}: RMS_T = {rms:.4f} {unit} (divisor n), {qgis} {unit} (divisor n − N); {within}/{n} within RMS_T; verdict: {verdict}.</source>
            <translation>درجهٔ {order}: ⁦RMS_T = {rms:.4f} {unit}⁩ (مقسوم‌علیه n)، {qgis} {unit} (مقسوم‌علیه n − N)؛ {within}/{n} در محدودهٔ RMS_T؛ نتیجه: {verdict}.</translation>
        </message>
        <message>
            <source>Recommended polynomial order: {order}.</source>
            <translation>درجهٔ پیشنهادی چندجمله‌ای: {order}.</translation>
        </message>
        <message>
            <source>No polynomial order has enough redundancy to be recommended (n ≥ 5, 9, 15 GCPs for orders 1, 2, 3).</source>
            <translation>هیچ درجه‌ای از چندجمله‌ای افزونگی کافی برای پیشنهاد ندارد (n ≥ 5، 9، 15 نقطهٔ کنترل زمینی برای درجه‌های 1، 2، 3).</translation>
        </message>
    </context>
    <context>
        <name>GeomaticsAlgorithm</name>
        <message>
            <source>LiDAR ground filtering</source>
            <translation>فیلتر کردن نقاط زمینی لایدار</translation>
        </message>
        <message>
            <source>Terrain models</source>
            <translation>مدل‌های رقومی زمین</translation>
        </message>
        <message>
            <source>Image rectification</source>
            <translation>تصحیح هندسی تصویر</translation>
        </message>
        <message>
            <source>Photogrammetry</source>
            <translation>فتوگرامتری</translation>
        </message>
        <message>
            <source>Accuracy assessment</source>
            <translation>ارزیابی دقت</translation>
        </message>
        <message>
            <source>Cancelled by the user; no output was written.</source>
            <translation>کاربر عملیات را لغو کرد؛ هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Out of memory. Use a coarser cell size, a smaller extent or fewer points; no output was written.</source>
            <translation>حافظه کافی نیست. اندازهٔ سلول بزرگ‌تر، محدودهٔ کوچک‌تر یا نقاط کمتری به کار ببرید؛ هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Remove low outliers first (class 7)</source>
            <translation>حذف نقاط پرت پایین در آغاز (کلاس 7)</translation>
        </message>
        <message>
            <source>Low-outlier search cell (m)</source>
            <translation>سلول جست‌وجوی نقاط پرت پایین (متر)</translation>
        </message>
        <message>
            <source>Low-outlier depth below neighbours (m)</source>
            <translation>عمق نقطهٔ پرت پایین نسبت به همسایه‌ها (متر)</translation>
        </message>
        <message>
            <source>Report language</source>
            <translation>زبان گزارش</translation>
        </message>
        <message>
            <source>Interface language</source>
            <translation>زبان رابط کاربری</translation>
        </message>
        <message>
            <source>Terminated; no output was written.</source>
            <translation>اجرا متوقف شد؛ هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>The point-cloud layer '{name}' is not a local .las/.laz file ({source}): export it to LAS/LAZ first.</source>
            <translation>لایهٔ ابر نقاط '{name}' یک فایل محلی ‎.las/.laz‏ نیست ({source}): ابتدا آن را به LAS/LAZ صادر کنید.</translation>
        </message>
        <message>
            <source>Created, never classified</source>
            <translation>ایجادشده، هرگز کلاس‌بندی‌نشده</translation>
        </message>
        <message>
            <source>Unclassified</source>
            <translation>کلاس‌بندی‌نشده</translation>
        </message>
        <message>
            <source>Ground</source>
            <translation>زمین</translation>
        </message>
        <message>
            <source>Low vegetation</source>
            <translation>پوشش گیاهی کوتاه</translation>
        </message>
        <message>
            <source>Medium vegetation</source>
            <translation>پوشش گیاهی متوسط</translation>
        </message>
        <message>
            <source>High vegetation</source>
            <translation>پوشش گیاهی بلند</translation>
        </message>
        <message>
            <source>Building</source>
            <translation>ساختمان</translation>
        </message>
        <message>
            <source>Low point (noise)</source>
            <translation>نقطهٔ پایین (نویز)</translation>
        </message>
        <message>
            <source>Reserved (model key-point)</source>
            <translation>رزروشده (نقطهٔ کلیدی مدل)</translation>
        </message>
        <message>
            <source>Water</source>
            <translation>آب</translation>
        </message>
        <message>
            <source>Rail</source>
            <translation>ریل</translation>
        </message>
        <message>
            <source>Road surface</source>
            <translation>سطح جاده</translation>
        </message>
        <message>
            <source>Reserved (overlap)</source>
            <translation>رزروشده (هم‌پوشانی)</translation>
        </message>
        <message>
            <source>Wire – guard (shield)</source>
            <translation>سیم – محافظ (شیلد)</translation>
        </message>
        <message>
            <source>Wire – conductor (phase)</source>
            <translation>سیم – رسانا (فاز)</translation>
        </message>
        <message>
            <source>Transmission tower</source>
            <translation>دکل انتقال نیرو</translation>
        </message>
        <message>
            <source>Wire-structure connector (insulator)</source>
            <translation>اتصال سیم به سازه (مقره)</translation>
        </message>
        <message>
            <source>Bridge deck</source>
            <translation>عرشهٔ پل</translation>
        </message>
        <message>
            <source>High noise</source>
            <translation>نویز بالا</translation>
        </message>
        <message>
            <source>Overhead structure</source>
            <translation>سازهٔ هوایی</translation>
        </message>
        <message>
            <source>Ignored ground</source>
            <translation>زمین نادیده‌گرفته</translation>
        </message>
        <message>
            <source>Snow</source>
            <translation>برف</translation>
        </message>
        <message>
            <source>Temporal exclusion</source>
            <translation>حذف زمانی</translation>
        </message>
        <message>
            <source>Example</source>
            <translation>مثال</translation>
        </message>
        <message>
            <source>Parameters</source>
            <translation>پارامترها</translation>
        </message>
        <message>
            <source>Also returned</source>
            <translation>خروجی‌های دیگر</translation>
        </message>
        <message>
            <source>default: {}</source>
            <translation>پیش‌فرض: {}</translation>
        </message>
        <message>
            <source>optional</source>
            <translation>اختیاری</translation>
        </message>
        <message>
            <source>advanced</source>
            <translation>پیشرفته</translation>
        </message>
        <message>
            <source>yes</source>
            <translation>بله</translation>
        </message>
        <message>
            <source>no</source>
            <translation>خیر</translation>
        </message>
        <message>
            <source>Check points used</source>
            <translation>نقاط چک به‌کاررفته</translation>
        </message>
        <message>
            <source>Check points outside the DTM</source>
            <translation>نقاط چک بیرون از DTM</translation>
        </message>
        <message>
            <source>Check points on DTM nodata</source>
            <translation>نقاط چک روی سلول‌های بدون داده در DTM</translation>
        </message>
        <message>
            <source>Mean error (m)</source>
            <translation>میانگین خطا (متر)</translation>
        </message>
        <message>
            <source>Mean absolute error (m)</source>
            <translation>میانگین خطای مطلق (متر)</translation>
        </message>
        <message>
            <source>RMSE (m)</source>
            <translation>ریشهٔ میانگین مربع خطا RMSE (متر)</translation>
        </message>
        <message>
            <source>Standard deviation of the errors (m)</source>
            <translation>انحراف معیار خطاها (متر)</translation>
        </message>
        <message>
            <source>Maximum absolute error (m)</source>
            <translation>بیشینهٔ خطای مطلق (متر)</translation>
        </message>
        <message>
            <source>Pearson r</source>
            <translation>ضریب همبستگی پیرسون r</translation>
        </message>
        <message>
            <source>R²</source>
            <translation>ضریب تعیین R²</translation>
        </message>
        <message>
            <source>NMAD (m)</source>
            <translation>انحراف مطلق میانه‌ای نرمال‌شده NMAD (متر)</translation>
        </message>
        <message>
            <source>Vertical accuracy at 95 % = 1.96·RMSE (m)</source>
            <translation>دقت قائم در 95 % = 1.96·RMSE (متر)</translation>
        </message>
        <message>
            <source>reference ground → filtered ground</source>
            <translation>زمین در مرجع ← زمین پس از فیلتر</translation>
        </message>
        <message>
            <source>reference ground → filtered object (Type I)</source>
            <translation>زمین در مرجع ← عارضه پس از فیلتر (نوع I)</translation>
        </message>
        <message>
            <source>reference object → filtered ground (Type II)</source>
            <translation>عارضه در مرجع ← زمین پس از فیلتر (نوع II)</translation>
        </message>
        <message>
            <source>reference object → filtered object</source>
            <translation>عارضه در مرجع ← عارضه پس از فیلتر</translation>
        </message>
        <message>
            <source>points</source>
            <translation>تعداد نقاط</translation>
        </message>
        <message>
            <source>Type I error (%)</source>
            <translation>خطای نوع اول (٪)</translation>
        </message>
        <message>
            <source>Type II error (%)</source>
            <translation>خطای نوع دوم (٪)</translation>
        </message>
        <message>
            <source>Total error (%)</source>
            <translation>خطای کل (٪)</translation>
        </message>
        <message>
            <source>Cohen's kappa (%)</source>
            <translation>ضریب کاپای کوهن (%)</translation>
        </message>
        <message>
            <source>Nearest neighbour (near)</source>
            <translation>نزدیک‌ترین همسایه (near)</translation>
        </message>
        <message>
            <source>Cubic convolution (cubic)</source>
            <translation>پیچش مکعبی (cubic)</translation>
        </message>
        <message>
            <source>Cubic spline (cubicspline)</source>
            <translation>اسپلاین مکعبی (cubicspline)</translation>
        </message>
        <message>
            <source>Lanczos windowed sinc (lanczos)</source>
            <translation>تابع sinc پنجره‌ای Lanczos (lanczos)</translation>
        </message>
        <message>
            <source>Most frequent value (mode)</source>
            <translation>پرتکرارترین مقدار (mode)</translation>
        </message>
        <message>
            <source>RMS_x (map units, divisor n)</source>
            <translation>RMS_x (واحد نقشه، مقسوم‌علیه n)</translation>
        </message>
        <message>
            <source>RMS_y (map units, divisor n)</source>
            <translation>RMS_y (واحد نقشه، مقسوم‌علیه n)</translation>
        </message>
        <message>
            <source>RMS_T (map units, divisor n)</source>
            <translation>RMS_T (واحد نقشه، مقسوم‌علیه n)</translation>
        </message>
        <message>
            <source>RMS_T with divisor n − N (QGIS Georeferencer)</source>
            <translation>RMS_T با مقسوم‌علیه n − N (زمین‌مرجع‌ساز QGIS)</translation>
        </message>
        <message>
            <source>Ground resolution GR (map units/pixel)</source>
            <translation>تفکیک زمینی GR (واحد نقشه/پیکسل)</translation>
        </message>
        <message>
            <source>Map scale number S = 20000·GR</source>
            <translation>عدد مقیاس نقشه S = 20000·GR</translation>
        </message>
        <message>
            <source>GCPs used in the fit</source>
            <translation>نقاط کنترل به‌کاررفته در برازش</translation>
        </message>
        <message>
            <source>Redundancy n − N</source>
            <translation>درجهٔ آزادی اضافی n − N</translation>
        </message>
        <message>
            <source>Points with RMS_i ≤ RMS_T</source>
            <translation>نقاط با RMS_i ≤ RMS_T</translation>
        </message>
        <message>
            <source>Leave-one-out RMS_T (map units)</source>
            <translation>RMS_T به روش یکی‌کنارگذاری (واحد نقشه)</translation>
        </message>
        <message>
            <source>Check-point RMS_T (map units)</source>
            <translation>RMS_T نقاط چک (واحد نقشه)</translation>
        </message>
        <message>
            <source>Independent check points</source>
            <translation>نقاط چک مستقل</translation>
        </message>
        <message>
            <source>Recommended order (0 = none)</source>
            <translation>مرتبهٔ پیشنهادی (0 = هیچ)</translation>
        </message>
        <message>
            <source>Accepted by criteria C4–C6 (1/0)</source>
            <translation>پذیرفته طبق معیارهای C4–C6 (1/0)</translation>
        </message>
        <message>
            <source>GCPs dropped by the refinement</source>
            <translation>نقاط حذف‌شده در پالایش</translation>
        </message>
        <message>
            <source>Check-point (else leave-one-out) RMS_T of the transformation used</source>
            <translation>RMS_T نقاط چک (وگرنه به روش یکی‌کنارگذاری) برای تبدیل به‌کاررفته</translation>
        </message>
        <message>
            <source>Colour ramp</source>
            <translation>طیف رنگی</translation>
        </message>
        <message>
            <source>Hillshade</source>
            <translation>سایه‌روشن</translation>
        </message>
        <message>
            <source>Cut (surface lowered)</source>
            <translation>برداشت (سطح پایین رفته)</translation>
        </message>
        <message>
            <source>Fill (surface raised)</source>
            <translation>خاکریز (سطح بالا آمده)</translation>
        </message>
        <message>
            <source>Could not style the layer {name}: {error}</source>
            <translation>سبک‌دهی لایهٔ {name} ممکن نشد: {error}</translation>
        </message>
        <message>
            <source>Linear</source>
            <translation>خطی (linear)</translation>
        </message>
        <message>
            <source>Power</source>
            <translation>توانی (power)</translation>
        </message>
        <message>
            <source>Gaussian</source>
            <translation>گاوسی (gaussian)</translation>
        </message>
        <message>
            <source>Spherical</source>
            <translation>کروی (spherical)</translation>
        </message>
        <message>
            <source>Exponential</source>
            <translation>نمایی (exponential)</translation>
        </message>
        <message>
            <source>Bilinear</source>
            <translation>دوخطی</translation>
        </message>
        <message>
            <source>Average</source>
            <translation>میانگین (average)</translation>
        </message>
        <message>
            <source>The data are in {} horizontally and {} vertically; they are converted to metres, so every length you give and every length in this log is in metres.</source>
            <translation>داده‌ها در افق بر حسب {} و در ارتفاع بر حسب {} هستند؛ به متر تبدیل می‌شوند، پس هر طولی که می‌دهید و هر طول در این گزارش کار به متر است.</translation>
        </message>
        <message>
            <source>Project name (shown in the report)</source>
            <translation>نام پروژه (در گزارش نمایش داده می‌شود)</translation>
        </message>
        <message>
            <source>Operator (shown in the report)</source>
            <translation>کاربر عامل (در گزارش نمایش داده می‌شود)</translation>
        </message>
        <message>
            <source>Set-up</source>
            <translation>تنظیمات</translation>
        </message>
        <message>
            <source>Pick a loaded point-cloud layer or a .las, .laz or .copc.laz file.</source>
            <translation>یک لایهٔ ابر نقاط بارشده یا یک فایل ‎.las‏، ‎.laz‏ یا ‎.copc.laz‏ انتخاب کنید.</translation>
        </message>
        <message>
            <source>This QGIS build has no PDAL point-cloud provider: .las/.laz files cannot be loaded as layers here, COPC files (.copc.laz) can (QGIS 3.26 and later read them without PDAL). Give the .las, .laz or .copc.laz file.</source>
            <translation>این نسخهٔ QGIS ارائه‌دهندهٔ ابر نقاط PDAL ندارد: فایل‌های ‎.las/.laz‏ را اینجا نمی‌توان به‌صورت لایه بار کرد، اما فایل‌های COPC ‏(‎.copc.laz‏) را می‌توان (QGIS 3.26 و نسخه‌های بعدی آن‌ها را بدون PDAL می‌خوانند). فایل ‎.las‏، ‎.laz‏ یا ‎.copc.laz‏ را بدهید.</translation>
        </message>
        <message>
            <source>This QGIS build has no PDAL point-cloud provider, so point clouds cannot be loaded as layers (COPC needs QGIS 3.26 or later): give the .las, .laz or .copc.laz file.</source>
            <translation>این نسخهٔ QGIS ارائه‌دهندهٔ ابر نقاط PDAL ندارد، پس ابرهای نقاط را نمی‌توان به‌صورت لایه بار کرد (COPC به QGIS 3.26 یا جدیدتر نیاز دارد): فایل ‎.las‏، ‎.laz‏ یا ‎.copc.laz‏ را بدهید.</translation>
        </message>
        <message>
            <source>Its default was chosen by leave-one-sample-out cross-validation over the ISPRS samples and synthetic forest, cliff, lake and bridge scenes (benchmarks/results/defaults.md).</source>
            <translation>پیش‌فرض آن با اعتبارسنجی متقابل حذف‌یک‌نمونه روی نمونه‌های ISPRS و صحنه‌های مصنوعی جنگل، صخره، دریاچه و پل انتخاب شده است (benchmarks/results/defaults.md).</translation>
        </message>
        <message>
            <source>HTML files (*.html)</source>
            <translation>پرونده‌های HTML (*.html)</translation>
        </message>
    </context>
    <context>
        <name>GeomaticsProvider</name>
        <message>
            <source>Geomatics Toolbox</source>
            <translation>جعبه‌ابزار ژئوماتیک</translation>
        </message>
        <message>
            <source>LiDAR to DTM with accuracy</source>
            <translation>از LiDAR تا DTM همراه با دقت</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>DTM cell size (m)</source>
            <translation>اندازهٔ سلول مدل زمین (متر)</translation>
        </message>
        <message>
            <source>IDW power</source>
            <translation>توان IDW</translation>
        </message>
        <message>
            <source>Fill data gaps in the DTM (interpolate far from ground points)</source>
            <translation>پر کردن شکاف‌های داده در DTM (درون‌یابی دور از نقاط زمین)</translation>
        </message>
        <message>
            <source>CRS override for a cloud without a CRS record</source>
            <translation>سیستم مختصات جایگزین برای ابری بدون رکورد سیستم مختصات</translation>
        </message>
        <message>
            <source>Check points (point layer)</source>
            <translation>نقاط چک (لایهٔ نقطه‌ای)</translation>
        </message>
        <message>
            <source>Check points (CSV/TXT file: id,x,y,z)</source>
            <translation>نقاط چک (فایل CSV/TXT: ‏id,x,y,z)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>گزارش فیلتر زمین</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>مدل رقومی زمین (DTM)</translation>
        </message>
        <message>
            <source>DTM report</source>
            <translation>گزارش مدل رقومی زمین</translation>
        </message>
        <message>
            <source>Check-point residuals</source>
            <translation>باقیمانده‌های نقاط چک</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>گزارش دقت مدل رقومی زمین</translation>
        </message>
        <message>
            <source>The editable model of 'LiDAR to DTM with accuracy': the same steps, defaults and results; open it in the Model Designer to change a step.</source>
            <translation>مدل ویرایش‌پذیرِ 'از LiDAR تا DTM همراه با دقت': همان گام‌ها، همان پیش‌فرض‌ها و همان نتایج؛ برای تغییر یک گام آن را در طراح مدل باز کنید.</translation>
        </message>
        <message>
            <source>&lt;p&gt;Ground filter (recommended) → DTM by IDW → DTM accuracy against check points, as a Processing model you can open and change in the Model Designer. With its defaults it gives the same classified cloud, DTM and RMSE, bit for bit, as the one-step algorithm 'LiDAR to DTM with accuracy' and as the three algorithms run one after another. Its steps write temporary files and a last step publishes them all or none: when a step fails, nothing is left at any destination.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;: the point cloud (LAS/LAZ, projected CRS), the DTM cell size (m, default 1), the IDW power (default 2), fill data gaps (default no), a CRS for a cloud without one, and the check points (a point layer or a CSV/TXT file id,x,y,z).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Outputs&lt;/b&gt;: classified point cloud, DTM, DTM accuracy report; optionally the ground filter report, the DTM report and the check-point residuals.&lt;/p&gt;</source>
            <translation>&lt;p&gt;فیلتر زمین (پیشنهادی) ← مدل رقومی زمین با IDW ← دقت مدل رقومی زمین در برابر نقاط چک، به‌صورت یک مدل پردازش که می‌توانید آن را در طراح مدل باز کنید و تغییر دهید. با پیش‌فرض‌هایش همان ابر نقاط طبقه‌بندی‌شده، همان مدل رقومی زمین و همان RMSE را، بیت به بیت، می‌دهد که الگوریتم تک‌گامی 'از LiDAR تا DTM همراه با دقت' و سه الگوریتمِ اجراشده پشت سر هم می‌دهند. گام‌هایش فایل‌های موقت می‌نویسند و گامی پایانی همه را با هم منتشر می‌کند یا هیچ‌کدام را: اگر گامی شکست بخورد، در هیچ مقصدی چیزی نمی‌ماند.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;: ابر نقاط (LAS/LAZ، سیستم مختصات تصویری)، اندازهٔ سلول DTM (متر، پیش‌فرض 1)، توان IDW (پیش‌فرض 2)، پر کردن شکاف‌های داده (پیش‌فرض خیر)، سیستم مختصات برای ابری که ندارد، و نقاط چک (لایهٔ نقطه‌ای یا فایل CSV/TXT ‏id,x,y,z).&lt;/p&gt;&lt;p&gt;&lt;b&gt;خروجی‌ها&lt;/b&gt;: ابر نقاط طبقه‌بندی‌شده، مدل رقومی زمین، گزارش دقت مدل رقومی زمین؛ و به‌اختیار گزارش فیلتر زمین، گزارش مدل رقومی زمین و باقیمانده‌های نقاط چک.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Project name (shown in the report)</source>
            <translation>نام پروژه (در گزارش نمایش داده می‌شود)</translation>
        </message>
        <message>
            <source>Operator (shown in the report)</source>
            <translation>کاربر عامل (در گزارش نمایش داده می‌شود)</translation>
        </message>
    </context>
    <context>
        <name>GeomaticsToolboxPlugin</name>
        <message>
            <source>{packages} for the LiDAR algorithms</source>
            <translation>{packages} برای الگوریتم‌های لایدار</translation>
        </message>
        <message>
            <source>{packages} for the tile catalog</source>
            <translation>{packages} برای کاتالوگ کاشی‌ها</translation>
        </message>
        <message>
            <source>QGIS's Python lacks Python packages this toolbox needs: {missing}. The other algorithms work without them.</source>
            <translation>Python خودِ QGIS بسته‌هایی را که این جعبه‌ابزار لازم دارد ندارد: {missing}. الگوریتم‌های دیگر بدون آن‌ها کار می‌کنند.</translation>
        </message>
        <message>
            <source>Geomatics Toolbox</source>
            <translation>جعبه‌ابزار ژئوماتیک</translation>
        </message>
        <message>
            <source>Install them…</source>
            <translation>نصب آن‌ها…</translation>
        </message>
        <message>
            <source>{packages} for every algorithm</source>
            <translation>{packages} برای همهٔ الگوریتم‌ها</translation>
        </message>
        <message>
            <source>QGIS's Python lacks Python packages this toolbox needs: {missing}. Until they are installed only the installer is offered.</source>
            <translation>Python خودِ QGIS بسته‌هایی را که این جعبه‌ابزار لازم دارد ندارد: {missing}. تا نصب نشوند فقط نصب‌کننده در دسترس است.</translation>
        </message>
    </context>
    <context>
        <name>GroundFilterAccuracyAlgorithm</name>
        <message>
            <source>Ground filter accuracy</source>
            <translation>دقت فیلتر نقاط زمینی</translation>
        </message>
        <message>
            <source>lidar,ground,filter,accuracy,type i,type ii,total error,kappa,isprs,reference,confusion matrix</source>
            <translation>لایدار,زمین,فیلتر,دقت,نوع اول,نوع دوم,خطای کل,کاپا,isprs,مرجع,ماتریس درهم‌ریختگی</translation>
        </message>
        <message>
            <source>Filtered point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط فیلترشده (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Class dimension of the filtered cloud</source>
            <translation>بُعد کلاس ابر فیلترشده</translation>
        </message>
        <message>
            <source>Ground classes of the filtered cloud</source>
            <translation>کلاس‌های زمینی ابر فیلترشده</translation>
        </message>
        <message>
            <source>Reference point cloud (same points, same order)</source>
            <translation>ابر نقاط مرجع (همان نقاط، با همان ترتیب)</translation>
        </message>
        <message>
            <source>Reference class dimension</source>
            <translation>بُعد کلاس مرجع</translation>
        </message>
        <message>
            <source>Reference ground classes</source>
            <translation>کلاس‌های زمینی مرجع</translation>
        </message>
        <message>
            <source>Per-point error layer (user_data: 0 correct, 1 Type I, 2 Type II)</source>
            <translation>لایهٔ خطای نقطه‌به‌نقطه (user_data: 0 درست، 1 نوع اول، 2 نوع دوم)</translation>
        </message>
        <message>
            <source>Compares a filtered point cloud with reference labels using the measures of the ISPRS filter test (Sithole &amp;amp; Vosselman 2004): the cross matrix, Type I = b/(a+b), Type II = c/(c+d), total error and Cohen's kappa. An optional per-point error cloud shows where the filter fails.</source>
            <translation>ابر نقاط فیلترشده را با برچسب‌های مرجع و با سنجه‌های آزمون فیلتر ISPRS ‏(Sithole &amp;amp; Vosselman 2004) مقایسه می‌کند: ماتریس متقاطع، نوع اول = b/(a+b)، نوع دوم = c/(c+d)، خطای کل و ضریب کاپای کوهن. ابر خطای اختیاریِ نقطه‌به‌نقطه نشان می‌دهد فیلتر کجا شکست می‌خورد.</translation>
        </message>
        <message>
            <source>A list such as 2,8 is accepted; every other class counts as an object.</source>
            <translation>فهرستی مانند 2,8 پذیرفته است؛ هر کلاس دیگر عارضه به شمار می‌آید.</translation>
        </message>
        <message>
            <source>Checked: equal count and coordinates. When empty, the reference labels are read from another dimension of the filtered cloud.</source>
            <translation>برابری شمار و مختصات بررسی می‌شود. اگر خالی باشد، برچسب‌های مرجع از بُعد دیگری از ابر فیلترشده خوانده می‌شوند.</translation>
        </message>
        <message>
            <source>E.g. user_data or an extra dimension when there is no reference cloud.</source>
            <translation>مانند user_data یا یک بُعد اضافی وقتی ابر مرجع نیست.</translation>
        </message>
        <message>
            <source>A copy of the filtered cloud; style it by user_data to map the errors.</source>
            <translation>رونوشتی از ابر فیلترشده؛ آن را بر اساس user_data نمادپردازی کنید تا خطاها روی نقشه دیده شوند.</translation>
        </message>
        <message>
            <source>Ground filter accuracy report</source>
            <translation>گزارش دقت فیلتر زمین</translation>
        </message>
    </context>
    <context>
        <name>GroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (recommended)</source>
            <translation>فیلتر زمین (پیشنهادی)</translation>
        </message>
        <message>
            <source>Classifies ground in a LAS/LAZ cloud with no parameter to set.</source>
            <translation>زمین را در ابر LAS/LAZ بدون هیچ پارامتری که لازم به تنظیم باشد طبقه‌بندی می‌کند.</translation>
        </message>
        <message>
            <source>&lt;p&gt;References: Pingel, T. J., Clarke, K. C. &amp;amp; McBride, W. A. (2013), ISPRS J. Photogramm. Remote Sens. 77, 21–30; Zhang, K. et al. (2003), IEEE TGRS 41(4), 872–882.&lt;/p&gt;</source>
            <translation>&lt;p&gt;مراجع: Pingel, T. J., Clarke, K. C. &amp;amp; McBride, W. A. (2013), ISPRS J. Photogramm. Remote Sens. 77, 21–30؛ Zhang, K. et al. (2003), IEEE TGRS 41(4), 872–882.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Raster cell, 0 = derived (m)</source>
            <translation>سلول رستر، 0 = برگرفته (متر)</translation>
        </message>
        <message>
            <source>Largest window, &gt; largest building (m)</source>
            <translation>بزرگ‌ترین پنجره، &gt; بزرگ‌ترین ساختمان (متر)</translation>
        </message>
        <message>
            <source>Slope tolerance, 0 = derived (rise/run)</source>
            <translation>تلورانس شیب، 0 = برگرفته (ارتفاع/فاصله)</translation>
        </message>
        <message>
            <source>Refinement passes</source>
            <translation>گذرهای پالایش</translation>
        </message>
        <message>
            <source>Remove low outliers first (class 7)</source>
            <translation>حذف نقاط پرت پایین در آغاز (کلاس 7)</translation>
        </message>
        <message>
            <source>Low-outlier search cell (m)</source>
            <translation>سلول جست‌وجوی نقاط پرت پایین (متر)</translation>
        </message>
        <message>
            <source>Low-outlier depth below neighbours (m)</source>
            <translation>عمق نقطهٔ پرت پایین نسبت به همسایه‌ها (متر)</translation>
        </message>
        <message>
            <source>0 = derived from the point density (about 1 m).</source>
            <translation>0 = از تراکم نقاط به دست می‌آید (حدود 1 متر).</translation>
        </message>
        <message>
            <source>Must exceed the largest building.</source>
            <translation>باید از بزرگ‌ترین ساختمان بزرگ‌تر باشد.</translation>
        </message>
        <message>
            <source>0 = half the local terrain slope (0.10 to 0.60).</source>
            <translation>0 = نصف شیب محلی زمین (0.10 تا 0.60).</translation>
        </message>
        <message>
            <source>Passes that rebuild the terrain from the accepted points.</source>
            <translation>گذرهایی که زمین را از نقاط پذیرفته‌شده بازسازی می‌کنند.</translation>
        </message>
        <message>
            <source>Height tolerance, 0 = derived (m)</source>
            <translation>تلورانس ارتفاع، 0 = برگرفته (متر)</translation>
        </message>
        <message>
            <source>Recommended ground filter: window {} m, {} refinement passes; cell and tolerances derived from the cloud (see the report)</source>
            <translation>فیلتر زمین پیشنهادی: پنجره {} متر، {} گذر پالایش؛ سلول و تلورانس‌ها برگرفته از ابر (گزارش را ببینید)</translation>
        </message>
        <message>
            <source>0 = 0.35 × the mean point spacing, 0.25 to 0.5 m; plus 1.0 m per unit of terrain slope.</source>
            <translation>0 = ‏0.35 × میانگین فاصلهٔ نقاط، از 0.25 تا 0.5 متر؛ به‌علاوهٔ 1.0 متر به ازای هر واحد شیب زمین.</translation>
        </message>
        <message>
            <source>Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) and low noise (class 7) with no parameter to set: a progressive morphological filter (Pingel et al. 2013) whose cell, slope and height tolerances are derived from the cloud, applied to the terrain with its regional slope removed; terrain crests it removed are grown back, then passes rebuild the terrain and re-test every point. Under a closed canopy lone ground returns are kept, so the terrain never climbs into the trees; water classified 9 in the input keeps its class, and flat, sparse patches that look like water get class 1, never ground. The report lists every value derived and warns on hard clouds. Total error with each sample held out of the choice of the defaults (8 ISPRS samples, 4 real vendor-classified files): 3.31 % on the ISPRS samples, 0.43 % on the real files (SMRF with PDAL's defaults: 5.75 % and 2.65 %); ISPRS mean at the defaults 3.27 %.</source>
            <translation>ابر نقطهٔ LAS/LAZ را بدون هیچ پارامتری به زمین (کلاس 2)، نقاط دیگر (کلاس 1) و نویز پایین (کلاس 7) طبقه‌بندی می‌کند: یک فیلتر ریخت‌شناسی تدریجی (Pingel et al. 2013) که سلول و رواداری‌های شیب و ارتفاع آن از خود ابر به دست می‌آید و روی زمینِ بدون شیب منطقه‌ای اعمال می‌شود؛ تیغه‌های زمین را که حذف کرده است باز می‌گرداند، سپس گذرهایی زمین را بازسازی و هر نقطه را دوباره آزمون می‌کنند. زیر تاج پوشش بسته بازگشت‌های تنهای زمین نگه داشته می‌شوند، پس زمین هرگز به درون درختان بالا نمی‌رود؛ آبی که در ورودی کلاس 9 دارد کلاس خود را نگه می‌دارد و لکه‌های هموار و پراکنده‌ای که شبیه آب‌اند کلاس 1 می‌گیرند و هرگز زمین نمی‌شوند. گزارش هر مقدار برگرفته را فهرست می‌کند و دربارهٔ ابرهای دشوار هشدار می‌دهد. خطای کل وقتی هر نمونه از انتخاب پیش‌فرض‌ها کنار گذاشته شود (8 نمونهٔ ISPRS و 4 فایل واقعی که تأمین‌کننده طبقه‌بندی کرده است): ‏3.31 % روی نمونه‌های ISPRS و 0.43 % روی فایل‌های واقعی (SMRF با پیش‌فرض‌های PDAL: ‏5.75 % و 2.65 %)؛ میانگین ISPRS با پیش‌فرض‌ها 3.27 %.</translation>
        </message>
    </context>
    <context>
        <name>GsdBatchAlgorithm</name>
        <message>
            <source>Table of cameras and distances</source>
            <translation>جدول دوربین‌ها و فاصله‌ها</translation>
        </message>
        <message>
            <source>Round GSD to 0.01 cm/px like the paper</source>
            <translation>گرد کردن GSD به ۰٫۰۱ سانتی‌متر/پیکسل مانند مقاله</translation>
        </message>
        <message>
            <source>GSD results</source>
            <translation>نتایج GSD</translation>
        </message>
        <message>
            <source>The table has no 'distance' column (m); columns found: {0}.</source>
            <translation>جدول ستون 'distance' (متر) ندارد؛ ستون‌های موجود: {0}.</translation>
        </message>
        <message>
            <source>Row {row}: unknown camera '{cam}'; known: {known}.</source>
            <translation>ردیف {row}: دوربین ناشناختهٔ '{cam}'؛ دوربین‌های شناخته: {known}.</translation>
        </message>
        <message>
            <source>Row {row}, column '{col}': '{val}' is not a number.</source>
            <translation>ردیف {row}، ستون '{col}': مقدار '{val}' عدد نیست.</translation>
        </message>
        <message>
            <source>Row {row}: missing {cols}; give the columns or a camera preset.</source>
            <translation>ردیف {row}: مقادیر {cols} وجود ندارد؛ ستون‌ها یا یک دوربین از پیش تعریف‌شده بدهید.</translation>
        </message>
        <message>
            <source>Row {row}: {err}</source>
            <translation>ردیف {row}: {err}</translation>
        </message>
        <message>
            <source>Could not write the result table: {0}</source>
            <translation>نوشتن جدول نتایج ممکن نشد: {0}</translation>
        </message>
        <message>
            <source>Runs the GSD and accuracy calculator for every row of a table (CSV, spreadsheet or any layer) and writes a table with the inputs and all results. A row with an invalid value stops the run with an error naming the row and the column.</source>
            <translation>محاسبه‌گر GSD و دقت را برای هر سطر یک جدول (CSV، صفحه‌گسترده یا هر لایه) اجرا می‌کند و جدولی با ورودی‌ها و همهٔ نتایج می‌نویسد. سطری با مقدار نامعتبر اجرا را با خطایی که سطر و ستون را نام می‌برد متوقف می‌کند.</translation>
        </message>
        <message>
            <source>Columns (any case): &lt;i&gt;camera&lt;/i&gt; (optional preset key: nikon_p100, dji_p4rtk, dji_p1_35, phaseone_ixm100_80), &lt;i&gt;distance&lt;/i&gt; (m, required), &lt;i&gt;sensor_width&lt;/i&gt; (mm), &lt;i&gt;image_width&lt;/i&gt; (px), &lt;i&gt;focal_length&lt;/i&gt; (mm) — required without a preset — and optionally sensor_height, image_height, target_gsd, k_m, k_s, pyramid_level, subsampling_step, observed_sx, observed_sy, observed_sz, observed_sxyz, observed_dense_std, forward_overlap, side_overlap, stereo_base (units as in the single calculator).</source>
            <translation>ستون‌ها (با هر حالت حروف): &lt;i&gt;camera&lt;/i&gt; (کلید پیش‌تنظیم اختیاری: nikon_p100، dji_p4rtk، dji_p1_35، phaseone_ixm100_80)، &lt;i&gt;distance&lt;/i&gt; (متر، الزامی)، &lt;i&gt;sensor_width&lt;/i&gt; (میلی‌متر)، &lt;i&gt;image_width&lt;/i&gt; (پیکسل)، &lt;i&gt;focal_length&lt;/i&gt; (میلی‌متر) — بدون پیش‌تنظیم الزامی — و به‌طور اختیاری sensor_height، image_height، target_gsd، k_m، k_s، pyramid_level، subsampling_step، observed_sx، observed_sy، observed_sz، observed_sxyz، observed_dense_std، forward_overlap، side_overlap، stereo_base (با همان واحدهای محاسبه‌گر تکی).</translation>
        </message>
        <message>
            <source>Rounds the GSD before the derived quantities, as the paper does.</source>
            <translation>GSD را پیش از کمیت‌های مشتق گرد می‌کند، همان‌گونه که مقاله می‌کند.</translation>
        </message>
        <message>
            <source>The input columns plus gsd_cm, footprint_width_m, sigma_xyz_mm, dense_resolution_cm and every other result.</source>
            <translation>ستون‌های ورودی به‌علاوهٔ gsd_cm، footprint_width_m، sigma_xyz_mm، dense_resolution_cm و همهٔ نتایج دیگر.</translation>
        </message>
        <message>
            <source>GSD calculator over a table of cameras and distances</source>
            <translation>محاسبه‌گر GSD برای جدولی از دوربین‌ها و فاصله‌ها</translation>
        </message>
    </context>
    <context>
        <name>GsdCalculatorAlgorithm</name>
        <message>
            <source>GSD and photogrammetric accuracy calculator</source>
            <translation>محاسبه‌گر GSD (فاصلهٔ نمونه‌برداری زمینی) و دقت فتوگرامتری</translation>
        </message>
        <message>
            <source>gsd,ground sampling distance,flying height,footprint,accuracy,photogrammetry,drone,flight planning,dense matching</source>
            <translation>gsd,فاصله نمونه‌برداری زمینی,ارتفاع پرواز,پوشش زمینی,دقت,فتوگرامتری,پهپاد,طراحی پرواز,تناظریابی متراکم</translation>
        </message>
        <message>
            <source>Custom (enter the values below)</source>
            <translation>سفارشی (مقادیر زیر را وارد کنید)</translation>
        </message>
        <message>
            <source>Camera preset</source>
            <translation>دوربین از پیش تعریف‌شده</translation>
        </message>
        <message>
            <source>Camera–object distance / flying height (m)</source>
            <translation>فاصلهٔ دوربین تا شیء / ارتفاع پرواز (متر)</translation>
        </message>
        <message>
            <source>Sensor height (mm)</source>
            <translation>ارتفاع حسگر (میلی‌متر)</translation>
        </message>
        <message>
            <source>Image height (px)</source>
            <translation>ارتفاع تصویر (پیکسل)</translation>
        </message>
        <message>
            <source>Target GSD (cm/px)</source>
            <translation>GSD هدف (سانتی‌متر/پیکسل)</translation>
        </message>
        <message>
            <source>Round GSD to 0.01 cm/px like the paper</source>
            <translation>گرد کردن GSD به ۰٫۰۱ سانتی‌متر/پیکسل مانند مقاله</translation>
        </message>
        <message>
            <source>Measurement factor k_m (px)</source>
            <translation>ضریب اندازه‌گیری k_m (پیکسل)</translation>
        </message>
        <message>
            <source>Safety factor k_s</source>
            <translation>ضریب اطمینان k_s</translation>
        </message>
        <message>
            <source>Dense matching pyramid level N_p (fraction, or % if checked below)</source>
            <translation>سطح هرم تصویر در تناظریابی متراکم N_p (کسر، یا درصد اگر گزینهٔ زیر فعال باشد)</translation>
        </message>
        <message>
            <source>Pyramid level is a percentage</source>
            <translation>سطح هرم به درصد است</translation>
        </message>
        <message>
            <source>Dense matching subsampling step T_s (px)</source>
            <translation>گام نمونه‌برداری تناظریابی متراکم T_s (پیکسل)</translation>
        </message>
        <message>
            <source>Observed σx (mm)</source>
            <translation>σx مشاهده‌شده (میلی‌متر)</translation>
        </message>
        <message>
            <source>Observed σy (mm)</source>
            <translation>σy مشاهده‌شده (میلی‌متر)</translation>
        </message>
        <message>
            <source>Observed σz (mm)</source>
            <translation>σz مشاهده‌شده (میلی‌متر)</translation>
        </message>
        <message>
            <source>Observed σxyz (mm)</source>
            <translation>σxyz مشاهده‌شده (میلی‌متر)</translation>
        </message>
        <message>
            <source>Observed dense-cloud std (cm)</source>
            <translation>انحراف معیار مشاهده‌شدهٔ ابر نقاط متراکم (سانتی‌متر)</translation>
        </message>
        <message>
            <source>Stereo base B (m) [extension]</source>
            <translation>طول باز استریو B (متر) [افزوده]</translation>
        </message>
        <message>
            <source>Forward overlap (%) [extension]</source>
            <translation>پوشش طولی (%) [افزوده]</translation>
        </message>
        <message>
            <source>Side overlap (%) [extension]</source>
            <translation>پوشش عرضی (%) [افزوده]</translation>
        </message>
        <message>
            <source>{name} ({unit}) is required with the Custom camera: enter it or choose a camera preset.</source>
            <translation>مقدار {name} ({unit}) برای دوربین سفارشی لازم است: آن را وارد کنید یا یک دوربین از پیش تعریف‌شده برگزینید.</translation>
        </message>
        <message>
            <source>Ground sampling distance, footprint and theoretical photogrammetric accuracy of a camera at a distance.</source>
            <translation>فاصلهٔ نمونه‌برداری زمینی، پوشش زمینی و دقت نظری فتوگرامتری یک دوربین در یک فاصلهٔ معین.</translation>
        </message>
        <message>
            <source>&lt;p&gt;&lt;b&gt;Formulas&lt;/b&gt;: GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;); footprint = D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;; σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD; σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;; matching step P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;; dense resolution R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD.&lt;/p&gt;</source>
            <translation>&lt;p&gt;&lt;b&gt;فرمول‌ها&lt;/b&gt;: &lt;span dir="ltr"&gt;GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;)&lt;/span&gt;؛ پوشش زمینی = &lt;span dir="ltr"&gt;D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;&lt;/span&gt;؛ &lt;span dir="ltr"&gt;σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD&lt;/span&gt;؛ &lt;span dir="ltr"&gt;σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;&lt;/span&gt;؛ گام تناظریابی &lt;span dir="ltr"&gt;P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;&lt;/span&gt;؛ تفکیک ابر متراکم &lt;span dir="ltr"&gt;R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD&lt;/span&gt;.&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Required with the Custom camera; overrides the preset.</source>
            <translation>با دوربین «سفارشی» الزامی است؛ بر مقدار پیش‌فرض دوربین مقدم است.</translation>
        </message>
        <message>
            <source>Sensor width (mm) — required with Custom</source>
            <translation>عرض حسگر (mm) — با «سفارشی» الزامی است</translation>
        </message>
        <message>
            <source>Image width (px) — required with Custom</source>
            <translation>عرض تصویر (px) — با «سفارشی» الزامی است</translation>
        </message>
        <message>
            <source>Focal length, true (mm) — required with Custom</source>
            <translation>فاصلهٔ کانونی واقعی (mm) — با «سفارشی» الزامی است</translation>
        </message>
        <message>
            <source>GSD calculator report</source>
            <translation>گزارش محاسبه‌گر GSD</translation>
        </message>
        <message>
            <source>Optional: gives the ratio of the observed to the theoretical accuracy.</source>
            <translation>اختیاری: نسبت دقت مشاهده‌شده به دقت نظری را می‌دهد.</translation>
        </message>
        <message>
            <source>Not in the paper: gives the exposure and line spacing.</source>
            <translation>در مقاله نیست: فاصلهٔ عکس‌ها و فاصلهٔ خطوط پرواز را می‌دهد.</translation>
        </message>
        <message>
            <source>Computes the ground sampling distance (GSD) and footprint of a camera at a given distance or flying height, and the theoretical accuracy of phototriangulation and of a dense-matching cloud (Al Khalil 2019). The paper's Nikon Coolpix P100 at 5.88 m (sensor width 6.123 mm, image width 3648 px, focal length 4.6 mm) gives a GSD of 0.21455 cm/px, σxyz 1.287 mm and a footprint 7.827 m wide.</source>
            <translation>فاصلهٔ نمونه‌برداری زمینی (GSD) و ردپای زمینی یک دوربین را در فاصله یا ارتفاع پرواز معین، و دقت نظری مثلث‌بندی هوایی و ابر تناظریابی متراکم را محاسبه می‌کند (Al Khalil 2019). دوربین Nikon Coolpix P100 مقاله در فاصلهٔ 5.88 متر (عرض حسگر 6.123 میلی‌متر، عرض تصویر 3648 پیکسل، فاصلهٔ کانونی 4.6 میلی‌متر) GSD برابر 0.21455 سانتی‌متر/پیکسل، σxyz برابر 1.287 میلی‌متر و ردپایی به عرض 7.827 متر می‌دهد.</translation>
        </message>
        <message>
            <source>Fills the sensor, image and focal length values; values you enter override the preset.</source>
            <translation>مقادیر حسگر، تصویر و فاصلهٔ کانونی را پر می‌کند؛ مقادیری که وارد می‌کنید بر پیش‌تنظیم مقدم‌اند.</translation>
        </message>
        <message>
            <source>Camera–object distance, or flying height above ground.</source>
            <translation>فاصلهٔ دوربین تا شیء، یا ارتفاع پرواز از سطح زمین.</translation>
        </message>
        <message>
            <source>The true focal length, not the 35 mm equivalent.</source>
            <translation>فاصلهٔ کانونی واقعی، نه معادل 35 میلی‌متری.</translation>
        </message>
        <message>
            <source>For the footprint height and the flight spacing.</source>
            <translation>برای ارتفاع ردپای زمینی و فاصلهٔ پروازها.</translation>
        </message>
        <message>
            <source>Gives the distance that achieves it.</source>
            <translation>فاصله‌ای را می‌دهد که به آن می‌رسد.</translation>
        </message>
        <message>
            <source>Rounds the GSD before the derived quantities, as the paper does.</source>
            <translation>GSD را پیش از کمیت‌های مشتق گرد می‌کند، همان‌گونه که مقاله می‌کند.</translation>
        </message>
        <message>
            <source>0.13 for an expert operator.</source>
            <translation>0.13 برای یک کاربر خبره.</translation>
        </message>
        <message>
            <source>A fraction in (0, 1], or a percentage.</source>
            <translation>کسری در بازهٔ (0، 1]، یا یک درصد.</translation>
        </message>
        <message>
            <source>Not in the paper: gives the normal-case σZ.</source>
            <translation>در مقاله نیست: σZ حالت نرمال را می‌دهد.</translation>
        </message>
    </context>
    <context>
        <name>IdwDtmAlgorithm</name>
        <message>
            <source>DTM by inverse distance weighting (IDW)</source>
            <translation>وزن‌دهی معکوس فاصله (IDW) برای مدل رقومی زمین</translation>
        </message>
        <message>
            <source>dtm,dem,idw,inverse distance,interpolation,lidar,ground,gdal_grid,invdistnn,raster</source>
            <translation>dtm,dem,idw,معکوس فاصله,درون‌یابی,لایدار,زمین,gdal_grid,invdistnn,رستر</translation>
        </message>
        <message>
            <source>Power p</source>
            <translation>توان p</translation>
        </message>
        <message>
            <source>Neighbours (0 = all within radius)</source>
            <translation>تعداد همسایه‌ها (0 = همهٔ نقاط درون شعاع)</translation>
        </message>
        <message>
            <source>Search radius (m, 0 = unlimited)</source>
            <translation>شعاع جست‌وجو (متر، 0 = نامحدود)</translation>
        </message>
        <message>
            <source>Minimum points</source>
            <translation>حداقل تعداد نقاط</translation>
        </message>
        <message>
            <source>IDW DTM</source>
            <translation>مدل رقومی زمین به روش IDW</translation>
        </message>
        <message>
            <source>IDW DTM report</source>
            <translation>گزارش مدل رقومی زمین به روش IDW</translation>
        </message>
        <message>
            <source>Interpolates a terrain raster from the ground points of a LAS/LAZ file by inverse distance weighting (Shepard 1968) over the nearest neighbours of each cell centre. It follows &lt;code&gt;gdal_grid -a invdistnn&lt;/code&gt; but works in blocks on a KD-tree, so a million points take seconds.</source>
            <translation>رستر زمین را از نقاط زمینی یک فایل LAS/LAZ با روش وزن‌دهی معکوس فاصله (Shepard 1968) بر پایهٔ نزدیک‌ترین همسایه‌های مرکز هر سلول درون‌یابی می‌کند. رفتار آن همانند &lt;code&gt;gdal_grid -a invdistnn&lt;/code&gt; است ولی به‌صورت بلوکی و با درخت KD کار می‌کند، پس یک میلیون نقطه در چند ثانیه پردازش می‌شود.</translation>
        </message>
        <message>
            <source>The seed paper found 3 best (RMSE 0.204 m at 62 GNSS points).</source>
            <translation>مقالهٔ مرجع مقدار 3 را بهترین یافت (RMSE = 0.204 m در 62 نقطهٔ GNSS).</translation>
        </message>
        <message>
            <source>Nearest points used per cell; 0 = every point within the search radius.</source>
            <translation>تعداد نزدیک‌ترین نقاط به‌کاررفته برای هر سلول؛ 0 = همهٔ نقاط درون شعاع جست‌وجو.</translation>
        </message>
        <message>
            <source>Only points within this distance are used.</source>
            <translation>فقط نقاط درون این فاصله به کار می‌روند.</translation>
        </message>
        <message>
            <source>Cells with fewer points within the search radius are nodata.</source>
            <translation>سلول‌هایی که نقاط کمتری درون شعاع جست‌وجو دارند بدون داده می‌مانند.</translation>
        </message>
        <message>
            <source>Points interpolated</source>
            <translation>نقاط درون‌یابی‌شده</translation>
        </message>
        <message>
            <source>Cells with a value</source>
            <translation>سلول‌های دارای مقدار</translation>
        </message>
        <message>
            <source>Nodata cells</source>
            <translation>سلول‌های بدون داده</translation>
        </message>
    </context>
    <context>
        <name>InstallDependenciesAlgorithm</name>
        <message>
            <source>Install the Python packages this toolbox needs</source>
            <translation>نصب بسته‌های Python مورد نیاز این جعبه‌ابزار</translation>
        </message>
        <message>
            <source>Installs laspy, lazrs, dask and distributed for QGIS's Python into a folder of this QGIS profile.</source>
            <translation>laspy، lazrs، dask و distributed را برای Python خودِ QGIS در پوشه‌ای از همین نمایهٔ کاربری QGIS نصب می‌کند.</translation>
        </message>
        <message>
            <source>install,pip,dependencies,packages,laspy,lazrs,dask,offline,wheels,setup</source>
            <translation>نصب,pip,وابستگی‌ها,بسته‌ها,laspy,lazrs,dask,آفلاین,wheels,راه‌اندازی</translation>
        </message>
        <message>
            <source>For computers without internet: a folder of wheel files (.whl) downloaded elsewhere with pip download for the same Python version and system. Empty: the package index pip is configured with.</source>
            <translation>برای رایانه‌های بدون اینترنت: پوشه‌ای از فایل‌های wheel ‏(.whl) که در جای دیگری با pip download برای همان نسخهٔ Python و همان سیستم‌عامل دریافت شده‌اند. خالی: نمایهٔ بسته‌ای که pip با آن پیکربندی شده است.</translation>
        </message>
        <message>
            <source>Folder of wheels (offline installation)</source>
            <translation>پوشهٔ فایل‌های wheel (نصب آفلاین)</translation>
        </message>
        <message>
            <source>Folder the packages are installed in</source>
            <translation>پوشه‌ای که بسته‌ها در آن نصب شدند</translation>
        </message>
        <message>
            <source>Packages installed</source>
            <translation>بسته‌های نصب‌شده</translation>
        </message>
        <message>
            <source>Packages still missing</source>
            <translation>بسته‌هایی که هنوز نیستند</translation>
        </message>
        <message>
            <source>pip commands run</source>
            <translation>فرمان‌های pip اجراشده</translation>
        </message>
        <message>
            <source>Python: {python}</source>
            <translation>Python: {python}</translation>
        </message>
        <message>
            <source>Folder: {folder}</source>
            <translation>پوشه: {folder}</translation>
        </message>
        <message>
            <source>Installed: {packages}</source>
            <translation>نصب شد: {packages}</translation>
        </message>
        <message>
            <source>Nothing to install: QGIS's Python already has every package.</source>
            <translation>چیزی برای نصب نیست: Python خودِ QGIS همهٔ بسته‌ها را دارد.</translation>
        </message>
        <message>
            <source>The LiDAR algorithms need laspy and lazrs, the tile catalog also dask and distributed; QGIS ships the rest (numpy, SciPy, GDAL), and where a QGIS build lacks SciPy it is installed too, for QGIS's own numpy. This installs the versions the toolbox was tested with, only those QGIS's Python lacks, with that Python's pip into a folder of the current QGIS profile: QGIS's own packages are never changed or replaced, and removing the folder undoes it. The log shows every command and everything pip prints.</source>
            <translation>الگوریتم‌های لایدار به laspy و lazrs نیاز دارند و کاتالوگ کاشی‌ها افزون بر آن به dask و distributed؛ بقیه (numpy، SciPy، GDAL) همراه QGIS است و اگر نسخه‌ای از QGIS ‏SciPy نداشته باشد، آن هم متناسب با numpy خودِ QGIS نصب می‌شود. این الگوریتم نسخه‌هایی را که جعبه‌ابزار با آن‌ها آزموده شده، فقط آن‌هایی را که Python خودِ QGIS ندارد، با pip همان Python در پوشه‌ای از نمایهٔ کاربری کنونی QGIS نصب می‌کند: بسته‌های خودِ QGIS هرگز تغییر نمی‌کنند یا جایگزین نمی‌شوند و با حذف پوشه همه‌چیز به حالت پیش بازمی‌گردد. گزارش اجرا هر فرمان و هرچه pip چاپ می‌کند را نشان می‌دهد.</translation>
        </message>
    </context>
    <context>
        <name>KrigingDtmAlgorithm</name>
        <message>
            <source>DTM by kriging (ordinary / universal)</source>
            <translation>کریجینگ (معمولی / عام) برای مدل رقومی زمین</translation>
        </message>
        <message>
            <source>dtm,dem,kriging,variogram,geostatistics,pykrige,interpolation,lidar,variance,cross-validation</source>
            <translation>dtm,dem,کریجینگ,واریوگرام,زمین‌آمار,pykrige,درون‌یابی,لایدار,واریانس,اعتبارسنجی متقابل</translation>
        </message>
        <message>
            <source>Kriging type</source>
            <translation>نوع کریجینگ</translation>
        </message>
        <message>
            <source>Ordinary</source>
            <translation>معمولی</translation>
        </message>
        <message>
            <source>Universal (linear drift)</source>
            <translation>عام (روند خطی)</translation>
        </message>
        <message>
            <source>Variogram model</source>
            <translation>مدل واریوگرام</translation>
        </message>
        <message>
            <source>Neighbours per cell</source>
            <translation>تعداد همسایه‌ها برای هر سلول</translation>
        </message>
        <message>
            <source>Points for the variogram fit</source>
            <translation>تعداد نقاط برای برازش واریوگرام</translation>
        </message>
        <message>
            <source>Lag classes</source>
            <translation>تعداد کلاس‌های فاصلهٔ تأخیر (lag)</translation>
        </message>
        <message>
            <source>Maximum lag (m, 0 = auto: local scale)</source>
            <translation>بیشینهٔ فاصلهٔ تأخیر (متر، 0 = خودکار: مقیاس محلی)</translation>
        </message>
        <message>
            <source>Cross-validation points (0 = off)</source>
            <translation>نقاط اعتبارسنجی متقابل (0 = خاموش)</translation>
        </message>
        <message>
            <source>Random seed</source>
            <translation>بذر تصادفی</translation>
        </message>
        <message>
            <source>Kriging DTM</source>
            <translation>مدل رقومی زمین به روش کریجینگ</translation>
        </message>
        <message>
            <source>Write standard deviation instead of variance</source>
            <translation>نوشتن انحراف معیار به‌جای واریانس</translation>
        </message>
        <message>
            <source>Kriging variance</source>
            <translation>واریانس کریجینگ</translation>
        </message>
        <message>
            <source>Variogram: {}</source>
            <translation>واریوگرام: {}</translation>
        </message>
        <message>
            <source>Variogram nugget (m², empty = fit)</source>
            <translation>اثر قطعه‌ای واریوگرام (متر²، خالی = برازش)</translation>
        </message>
        <message>
            <source>Variogram sill, nugget included (m², empty = fit)</source>
            <translation>آستانهٔ واریوگرام با اثر قطعه‌ای (متر²، خالی = برازش)</translation>
        </message>
        <message>
            <source>Variogram practical range (m, empty = fit)</source>
            <translation>دامنهٔ عملی واریوگرام (متر، خالی = برازش)</translation>
        </message>
        <message>
            <source>Linear variogram slope (m²/m)</source>
            <translation>شیب واریوگرام خطی (متر²/متر)</translation>
        </message>
        <message>
            <source>Power variogram scale</source>
            <translation>مقیاس واریوگرام توانی</translation>
        </message>
        <message>
            <source>Power variogram exponent (0–2)</source>
            <translation>توان واریوگرام توانی (0–2)</translation>
        </message>
        <message>
            <source>Variogram parameters as text (old form)</source>
            <translation>پارامترهای واریوگرام به‌صورت متن (شکل قدیمی)</translation>
        </message>
        <message>
            <source>Kriging DTM report</source>
            <translation>گزارش مدل رقومی زمین به روش کریجینگ</translation>
        </message>
        <message>
            <source>Kriges the ground points of a LAS/LAZ file onto a raster (ordinary kriging, or universal kriging with a linear drift) and can also write the kriging variance. The variogram is fitted on a random sample or given by you, and each cell is kriged from its nearest points, so a million points take about a minute.</source>
            <translation>نقاط زمینی یک فایل LAS/LAZ را با کریجینگ روی یک رستر درون‌یابی می‌کند (کریجینگ معمولی، یا کریجینگ عام با روند خطی) و می‌تواند واریانس کریجینگ را هم بنویسد. واریوگرام روی یک نمونهٔ تصادفی برازش می‌شود یا شما آن را می‌دهید، و هر سلول از نزدیک‌ترین نقاطش برآورد می‌شود، پس یک میلیون نقطه حدود یک دقیقه طول می‌کشد.</translation>
        </message>
        <message>
            <source>Give nugget, sill and range to skip the fit; the sill includes the nugget.</source>
            <translation>برای رد شدن از برازش، اثر قطعه‌ای، سقف و دامنه را بدهید؛ سقف شامل اثر قطعه‌ای است.</translation>
        </message>
        <message>
            <source>Linear model only.</source>
            <translation>فقط برای مدل خطی.</translation>
        </message>
        <message>
            <source>Power model only.</source>
            <translation>فقط برای مدل توانی.</translation>
        </message>
        <message>
            <source>Local kriging: the mean is re-estimated in every neighbourhood; as many neighbours as points (up to 6000) gives global kriging, identical to PyKrige.</source>
            <translation>کریجینگ محلی: میانگین در هر همسایگی دوباره برآورد می‌شود؛ اگر تعداد همسایه‌ها با تعداد نقاط برابر باشد (تا 6000)، کریجینگ سراسری و یکسان با PyKrige به دست می‌آید.</translation>
        </message>
        <message>
            <source>0 = three times the typical distance to the farthest neighbour used; for a field-scale fit give about half the extent.</source>
            <translation>0 = سه برابر فاصلهٔ معمول تا دورترین همسایهٔ به‌کاررفته؛ برای برازش در مقیاس کل منطقه حدود نیمی از گستره را بدهید.</translation>
        </message>
        <message>
            <source>Leave-one-out check on this many random points; an RMS standardised error near 1 means realistic variances.</source>
            <translation>اعتبارسنجی حذف‌یکی روی این تعداد نقطهٔ تصادفی؛ جذر میانگین مربعات خطای استانداردشدهٔ نزدیک به 1 یعنی واریانس‌ها واقع‌بینانه‌اند.</translation>
        </message>
        <message>
            <source>Makes the sample of the variogram fit reproducible.</source>
            <translation>نمونهٔ برازش واریوگرام را تکرارپذیر می‌کند.</translation>
        </message>
        <message>
            <source>In m², or in m as a standard deviation.</source>
            <translation>بر حسب m²، یا بر حسب m به‌صورت انحراف معیار.</translation>
        </message>
        <message>
            <source>Nugget</source>
            <translation>اثر قطعه‌ای (Nugget)</translation>
        </message>
        <message>
            <source>Sill</source>
            <translation>آستانه (Sill)</translation>
        </message>
        <message>
            <source>Range</source>
            <translation>برد</translation>
        </message>
        <message>
            <source>Points kriged</source>
            <translation>نقاط کریجینگ‌شده</translation>
        </message>
        <message>
            <source>Cells with a value</source>
            <translation>سلول‌های دارای مقدار</translation>
        </message>
        <message>
            <source>Cross-validation mean error</source>
            <translation>میانگین خطای اعتبارسنجی متقابل</translation>
        </message>
        <message>
            <source>Cross-validation RMSE</source>
            <translation>RMSE اعتبارسنجی متقابل</translation>
        </message>
        <message>
            <source>Cross-validation mean standardised error</source>
            <translation>میانگین خطای استانداردشدهٔ اعتبارسنجی متقابل</translation>
        </message>
    </context>
    <context>
        <name>LidarFilterMixin</name>
        <message>
            <source>{} points: {} ground, {} non-ground, {} low outliers; filter {:.1f} s</source>
            <translation>{} نقطه: {} زمینی، {} غیرزمینی، {} پرت پایین؛ فیلتر {:.1f} ثانیه</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
    </context>
    <context>
        <name>LidarQaAlgorithm</name>
        <message>
            <source>Point density and quality (with parameter advice)</source>
            <translation>تراکم و کیفیت نقاط (با توصیهٔ پارامترها)</translation>
        </message>
        <message>
            <source>Density rasters, gaps, duplicates and noise of a cloud, and the filter window and DTM cell its density supports.</source>
            <translation>رسترهای تراکم، شکاف‌ها، نقاط تکراری و نویز یک ابر، و پنجرهٔ فیلتر و سلول مدل رقومی زمین که تراکم آن پشتیبانی می‌کند.</translation>
        </message>
        <message>
            <source>density,quality,qa,lasinfo,gaps,duplicates,noise,scan angle,returns,advice,lidar</source>
            <translation>تراکم,کیفیت,qa,lasinfo,شکاف‌ها,تکراری‌ها,نویز,زاویهٔ اسکن,بازتاب‌ها,توصیه,لایدار</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Cell size (m)</source>
            <translation>اندازهٔ سلول (متر)</translation>
        </message>
        <message>
            <source>Ground classes</source>
            <translation>کلاس‌های زمین</translation>
        </message>
        <message>
            <source>Density rasters</source>
            <translation>رسترهای تراکم</translation>
        </message>
        <message>
            <source>Checks a LAS/LAZ cloud before processing: density of all, last and ground returns, gaps without ground, duplicates, noise share and scan angles. It then states which settings the density supports: ground filter window, DTM cell size, LOD1 only below 1 pt/m², and the radius and tile of the slope-based and LSQ filters.</source>
            <translation>یک ابر LAS/LAZ را پیش از پردازش بررسی می‌کند: تراکم همهٔ بازگشت‌ها، بازگشت‌های آخر و بازگشت‌های زمین، شکاف‌های بی‌زمین، نقاط تکراری، سهم نوفه و زاویه‌های اسکن. سپس می‌گوید تراکم از چه تنظیم‌هایی پشتیبانی می‌کند: پنجرهٔ فیلتر زمین، اندازهٔ سلول DTM، LOD1 فقط زیر 1 pt/m²، و شعاع فیلتر شیب و کاشی فیلتر LSQ.</translation>
        </message>
        <message>
            <source>In a projected CRS (metres); a cloud in degrees is refused.</source>
            <translation>در سامانهٔ مختصات تصویری (متر)؛ ابر بر حسب درجه پذیرفته نمی‌شود.</translation>
        </message>
        <message>
            <source>GeoTIFF with four bands: all returns, last returns, ground (pts/m²) and gap (1/0).</source>
            <translation>فایل GeoTIFF با چهار باند: همهٔ بازگشت‌ها، بازگشت‌های آخر، زمین (pts/m²) و شکاف (1/0).</translation>
        </message>
        <message>
            <source>Maps, histograms and the advice.</source>
            <translation>نقشه‌ها، بافت‌نگارها و توصیه‌ها.</translation>
        </message>
        <message>
            <source>Point density and quality report</source>
            <translation>گزارش تراکم و کیفیت نقاط</translation>
        </message>
        <message>
            <source>Density of all returns (pts/m²)</source>
            <translation>تراکم همهٔ بازتاب‌ها (نقطه بر مترمربع)</translation>
        </message>
        <message>
            <source>Ground density (pts/m²)</source>
            <translation>تراکم نقاط زمین (نقطه بر مترمربع)</translation>
        </message>
        <message>
            <source>Share of cells without ground</source>
            <translation>سهم سلول‌های بدون زمین</translation>
        </message>
        <message>
            <source>Duplicate points</source>
            <translation>نقاط تکراری</translation>
        </message>
        <message>
            <source>Noise share</source>
            <translation>سهم نویز</translation>
        </message>
        <message>
            <source>Ground filter window (m)</source>
            <translation>پنجرهٔ فیلتر زمین (متر)</translation>
        </message>
        <message>
            <source>Recommended DTM cell (m)</source>
            <translation>سلول پیشنهادی مدل رقومی زمین (متر)</translation>
        </message>
    </context>
    <context>
        <name>LidarToDtmAlgorithm</name>
        <message>
            <source>LiDAR to DTM with accuracy</source>
            <translation>از LiDAR تا DTM همراه با دقت</translation>
        </message>
        <message>
            <source>lidar,ground,filter,dtm,dem,idw,accuracy,rmse,check points,chain,all-or-nothing</source>
            <translation>لایدار,زمین,فیلتر,مدل رقومی زمین,dem,idw,دقت,rmse,نقاط چک,زنجیره,همه یا هیچ</translation>
        </message>
        <message>
            <source>DTM cell size (m)</source>
            <translation>اندازهٔ سلول مدل زمین (متر)</translation>
        </message>
        <message>
            <source>IDW power</source>
            <translation>توان IDW</translation>
        </message>
        <message>
            <source>IDW neighbours</source>
            <translation>تعداد همسایه‌های IDW</translation>
        </message>
        <message>
            <source>Fill data gaps in the DTM (interpolate far from ground points)</source>
            <translation>پر کردن شکاف‌های داده در DTM (درون‌یابی دور از نقاط زمین)</translation>
        </message>
        <message>
            <source>CRS override for a cloud without a CRS record</source>
            <translation>سیستم مختصات جایگزین برای ابری بدون رکورد سیستم مختصات</translation>
        </message>
        <message>
            <source>Check points (CSV/TXT file: id,x,y,z)</source>
            <translation>نقاط چک (فایل CSV/TXT: ‏id,x,y,z)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>مدل رقومی زمین (DTM)</translation>
        </message>
        <message>
            <source>Check-point residuals</source>
            <translation>باقیمانده‌های نقاط چک</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>گزارش دقت مدل رقومی زمین</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>گزارش فیلتر زمین</translation>
        </message>
        <message>
            <source>DTM report</source>
            <translation>گزارش مدل رقومی زمین</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط زمینی</translation>
        </message>
        <message>
            <source>The point cloud has no CRS record and no CRS was given; set the CRS parameter (e.g. EPSG:32632). No output was written.</source>
            <translation>ابر نقاط رکورد سیستم مختصات ندارد و سیستم مختصاتی هم داده نشده است؛ پارامتر CRS را تنظیم کنید (مثلاً EPSG:32632). هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>None of the {n} check points lies within the point cloud's extent (x {x0:.1f}–{x1:.1f}, y {y0:.1f}–{y1:.1f}); are they in another CRS? No output was written.</source>
            <translation>هیچ‌یک از {n} نقطهٔ چک درون گسترهٔ ابر نقاط نیست (x ‏{x0:.1f}–{x1:.1f}، y ‏{y0:.1f}–{y1:.1f})؛ آیا در سیستم مختصات دیگری‌اند؟ هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Choose the point cloud (a .las or .laz file).</source>
            <translation>ابر نقاط را انتخاب کنید (فایل ‎.las‏ یا ‎.laz‏).</translation>
        </message>
        <message>
            <source>Choose an output file for {}.</source>
            <translation>یک فایل خروجی برای {} انتخاب کنید.</translation>
        </message>
        <message>
            <source>Cell size must be &gt; 0 (metres); give e.g. 1.0.</source>
            <translation>اندازهٔ سلول باید &gt; 0 (متر) باشد؛ مثلاً 1.0 بدهید.</translation>
        </message>
        <message>
            <source>The ground filter found no ground point; no DTM can be interpolated. No output was written.</source>
            <translation>فیلتر زمین هیچ نقطهٔ زمینی نیافت؛ DTM قابل درون‌یابی نیست. هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Classifies the ground of a LiDAR point cloud, interpolates an IDW DTM from the ground points and measures its accuracy against check points, in one step. It writes all its outputs or none, and its results equal those of the three algorithms run one after another.</source>
            <translation>زمینِ یک ابر نقاط LiDAR را کلاس‌بندی می‌کند، از نقاط زمین یک DTM به روش IDW درون‌یابی می‌کند و دقت آن را با نقاط چک می‌سنجد، در یک گام. همهٔ خروجی‌ها را می‌نویسد یا هیچ‌کدام را، و نتایجش با اجرای پی‌درپی سه الگوریتم یکسان است.</translation>
        </message>
        <message>
            <source>In a projected CRS (metres).</source>
            <translation>در سامانهٔ مختصات تصویری (متر).</translation>
        </message>
        <message>
            <source>Give the layer or the file; duplicates and points outside the cloud's extent are refused before anything is written.</source>
            <translation>لایه یا فایل را بدهید؛ نقاط تکراری و نقاطِ بیرون از گسترهٔ ابر پیش از نوشتن هر چیزی رد می‌شوند.</translation>
        </message>
        <message>
            <source>Classified by the recommended ground filter (the improved least-squares filter where it is not installed).</source>
            <translation>کلاس‌بندی‌شده با فیلتر زمین توصیه‌شده (یا فیلتر کمترین مربعات بهبودیافته هرجا نصب نباشد).</translation>
        </message>
        <message>
            <source>The seed paper found 3 best (RMSE 0.204 m at 62 GNSS points).</source>
            <translation>مقالهٔ مرجع مقدار 3 را بهترین یافت (RMSE = 0.204 m در 62 نقطهٔ GNSS).</translation>
        </message>
    </context>
    <context>
        <name>LsqGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (least-squares polynomial)</source>
            <translation>فیلتر نقاط زمینی (چندجمله‌ای کمترین مربعات)</translation>
        </message>
        <message>
            <source>lidar,ground,filter,bare earth,dtm,classification,least squares,polynomial,tiles,las,laz,isprs</source>
            <translation>لایدار,زمین,فیلتر,زمین لخت,dtm,طبقه‌بندی,کمترین مربعات,چندجمله‌ای,کاشی‌ها,las,laz,isprs</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Polynomial order (1 or 2)</source>
            <translation>درجهٔ چندجمله‌ای (1 یا 2)</translation>
        </message>
        <message>
            <source>Tile size (m)</source>
            <translation>اندازهٔ کاشی (متر)</translation>
        </message>
        <message>
            <source>Threshold T (m)</source>
            <translation>آستانهٔ T (متر)</translation>
        </message>
        <message>
            <source>Mode</source>
            <translation>حالت</translation>
        </message>
        <message>
            <source>Faithful (the paper)</source>
            <translation>مطابق (روش مقاله)</translation>
        </message>
        <message>
            <source>Improved (ours, beyond the paper)</source>
            <translation>بهبودیافته (افزودهٔ ما، فراتر از مقاله)</translation>
        </message>
        <message>
            <source>Maximum iterations per tile</source>
            <translation>حداکثر تکرار در هر کاشی</translation>
        </message>
        <message>
            <source>Stop tolerance on min/max/mean/std (m)</source>
            <translation>تلورانس توقف برای کمینه/بیشینه/میانگین/انحراف معیار (متر)</translation>
        </message>
        <message>
            <source>Random fitting subset per tile (points, 0 = all)</source>
            <translation>زیرمجموعهٔ تصادفی برازش در هر کاشی (نقطه، 0 = همه)</translation>
        </message>
        <message>
            <source>Random seed of the subset</source>
            <translation>بذر تصادفی زیرمجموعه</translation>
        </message>
        <message>
            <source>Minimum points per tile (0 = 3 × coefficients)</source>
            <translation>حداقل نقاط هر کاشی (0 = 3 × تعداد ضرایب)</translation>
        </message>
        <message>
            <source>Under-populated tiles</source>
            <translation>کاشی‌های کم‌نقطه</translation>
        </message>
        <message>
            <source>Borrow the nearest fitted tile's surface</source>
            <translation>استفاده از سطح نزدیک‌ترین کاشی برازش‌شده</translation>
        </message>
        <message>
            <source>Leave their points unclassified (class 0)</source>
            <translation>طبقه‌بندی‌نشده ماندن نقاط آن‌ها (کلاس 0)</translation>
        </message>
        <message>
            <source>Rejection</source>
            <translation>شیوهٔ رد نقاط</translation>
        </message>
        <message>
            <source>Re-weighted each iteration (a point may return)</source>
            <translation>وزن‌دهی دوباره در هر تکرار (نقطه ممکن است بازگردد)</translation>
        </message>
        <message>
            <source>Cumulative (a rejected point stays out)</source>
            <translation>تجمعی (نقطهٔ ردشده بیرون می‌ماند)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>Ground points only</source>
            <translation>فقط نقاط زمینی</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط زمینی</translation>
        </message>
        <message>
            <source>Other (object) points</source>
            <translation>نقاط دیگر (عوارض)</translation>
        </message>
        <message>
            <source>Low-noise points</source>
            <translation>نقاط نویز پایین</translation>
        </message>
        <message>
            <source>Unclassified points</source>
            <translation>نقاط طبقه‌بندی‌نشده</translation>
        </message>
        <message>
            <source>Tiles</source>
            <translation>کاشی‌ها</translation>
        </message>
        <message>
            <source>Points per second</source>
            <translation>نقطه در ثانیه</translation>
        </message>
        <message>
            <source>Choose an output file for the classified cloud (OUTPUT, .laz or .las).</source>
            <translation>یک پروندهٔ خروجی برای ابر طبقه‌بندی‌شده انتخاب کنید (OUTPUT، با پسوند .laz یا .las).</translation>
        </message>
        <message>
            <source>Reading {p}</source>
            <translation>در حال خواندن {p}</translation>
        </message>
        <message>
            <source>{step}: {n} points kept, ZMin {a:.2f}, ZMax {b:.2f}, ZMean {m:.2f}, σ {s:.2f}; tiles iterating: {t}</source>
            <translation>{step}: {n} نقطه نگه داشته شد، ZMin {a:.2f}، ZMax {b:.2f}، ZMean {m:.2f}، σ {s:.2f}؛ کاشی‌های در حال تکرار: {t}</translation>
        </message>
        <message>
            <source>Ground {g}, other {o}, low noise {z}, unclassified {u}; {t} tiles; {s:.1f} s</source>
            <translation>زمینی {g}، سایر {o}، نویز پایین {z}، طبقه‌بندی‌نشده {u}؛ {t} کاشی؛ {s:.1f} ثانیه</translation>
        </message>
        <message>
            <source>Per-tile iteration statistics (CSV)</source>
            <translation>آماره‌های تکرار هر کاشی (CSV)</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>پرونده‌های CSV (*.csv)</translation>
        </message>
        <message>
            <source>Separates bare-earth points from buildings and vegetation in an airborne LiDAR cloud by fitting least-squares polynomial surfaces per square tile (Damascus Univ. J. Eng. Sci. 29(2), 2013). Points more than the threshold above the surface are dropped and the fit repeated until the height statistics settle; the rest become ground (class 2), the others class 1.</source>
            <translation>نقاط زمین لخت را از ساختمان‌ها و پوشش گیاهی در ابر نقاط LiDAR هوایی جدا می‌کند؛ با برازش سطوح چندجمله‌ای کمترین مربعات در هر کاشی مربعی (مجلهٔ علوم مهندسی دانشگاه دمشق 29(2)، 2013). نقاطی که بیش از آستانه بالای سطح‌اند کنار گذاشته می‌شوند و برازش تا پایدار شدن آمار ارتفاع تکرار می‌شود؛ باقی زمین (کلاس 2) و دیگران کلاس 1 می‌شوند.</translation>
        </message>
        <message>
            <source>1 = plane, 2 = quadratic surface (better on every sample of the paper).</source>
            <translation>1 = صفحه، 2 = سطح درجه‌دو (در همهٔ نمونه‌های مقاله بهتر).</translation>
        </message>
        <message>
            <source>Larger than the largest building, so that every tile holds ground (the paper: 100 m for large buildings, 50 m for small ones).</source>
            <translation>بزرگ‌تر از بزرگ‌ترین ساختمان، تا هر کاشی زمین داشته باشد (مقاله: 100 m برای ساختمان‌های بزرگ و 50 m برای کوچک).</translation>
        </message>
        <message>
            <source>0.5–1.0 m, larger on steeper terrain.</source>
            <translation>0.5 تا 1.0 m، در زمین‌های پرشیب‌تر بزرگ‌تر.</translation>
        </message>
        <message>
            <source>Faithful follows the paper. Improved (this toolbox's extension) fits coarse-to-fine overlapping tiles with a slope-dependent threshold: mean total error on the ISPRS samples 8.9 % → about 4.9 %, at about 15 times the time.</source>
            <translation>حالت وفادار از مقاله پیروی می‌کند. حالت بهبودیافته (افزودهٔ این جعبه‌ابزار) کاشی‌های هم‌پوشان را از درشت به ریز با آستانهٔ وابسته به شیب برازش می‌کند: میانگین خطای کل روی نمونه‌های ISPRS ‏8.9 % ← حدود 4.9 %، با حدود 15 برابر زمان.</translation>
        </message>
        <message>
            <source>Points far below their neighbours (multipath) get class 7 and take no part in the fit.</source>
            <translation>نقاطی که بسیار پایین‌تر از همسایه‌هایشان‌اند (چندمسیری) کلاس 7 می‌گیرند و در برازش شرکت نمی‌کنند.</translation>
        </message>
        <message>
            <source>The paper used 5000; every point is still classified.</source>
            <translation>مقاله 5000 به کار برد؛ با این حال همهٔ نقاط کلاس‌بندی می‌شوند.</translation>
        </message>
        <message>
            <source>Tiles with too few points borrow the nearest fitted surface, or their points stay class 0.</source>
            <translation>کاشی‌های کم‌نقطه نزدیک‌ترین سطح برازش‌شده را وام می‌گیرند، یا نقاطشان در کلاس 0 می‌مانند.</translation>
        </message>
        <message>
            <source>Re-weighted: a dropped point may come back when the surface moves; cumulative: dropped for good.</source>
            <translation>وزن‌دهی دوباره: نقطهٔ کنارگذاشته ممکن است با جابه‌جایی سطح بازگردد؛ تجمعی: برای همیشه کنار گذاشته می‌شود.</translation>
        </message>
        <message>
            <source>Every attribute, point format, scales, offsets, VLRs and CRS are copied unchanged; any earlier classification is replaced.</source>
            <translation>همهٔ ویژگی‌ها، قالب نقطه، مقیاس‌ها، آفست‌ها، VLRها و سامانهٔ مختصات بدون تغییر رونوشت می‌شوند؛ هر کلاس‌بندی پیشین جایگزین می‌شود.</translation>
        </message>
        <message>
            <source>Class counts, the per-iteration statistics of the paper's tables, a tile map and the speed.</source>
            <translation>شمار کلاس‌ها، آمار هر تکرار مانند جدول‌های مقاله، نقشهٔ کاشی‌ها و سرعت.</translation>
        </message>
        <message>
            <source>LSQ ground filter report</source>
            <translation>گزارش فیلتر زمین کمترین مربعات (LSQ)</translation>
        </message>
        <message>
            <source>Improved is the default: its total error is lower on each of the 8 ISPRS samples (mean 7.2 % against 21.3 %; 9.5 % against 29.6 % on the four it was not tuned on).</source>
            <translation>بهبودیافته پیش‌فرض است: خطای کل آن در هر یک از 8 نمونهٔ ISPRS کمتر است (میانگین 7.2 % در برابر 21.3 %؛ و 9.5 % در برابر 29.6 % روی چهار نمونه‌ای که روی آن‌ها تنظیم نشده است).</translation>
        </message>
    </context>
    <context>
        <name>PtdGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (progressive TIN densification)</source>
            <translation>فیلتر زمین (متراکم‌سازی تدریجی TIN)</translation>
        </message>
        <message>
            <source>Axelsson's progressive TIN densification ground filter.</source>
            <translation>فیلتر زمین با متراکم‌سازی تدریجی TIN (Axelsson).</translation>
        </message>
        <message>
            <source>Cell (m)</source>
            <translation>سلول (متر)</translation>
        </message>
        <message>
            <source>Parcel size, &gt; largest building (m)</source>
            <translation>اندازهٔ قطعه، &gt; بزرگ‌ترین ساختمان (متر)</translation>
        </message>
        <message>
            <source>Distance to facet (m)</source>
            <translation>فاصله تا وجه (متر)</translation>
        </message>
        <message>
            <source>Angle to vertices (degrees)</source>
            <translation>زاویه تا رأس‌ها (درجه)</translation>
        </message>
        <message>
            <source>Final distance (m)</source>
            <translation>فاصلهٔ نهایی (متر)</translation>
        </message>
        <message>
            <source>Low-noise depth (m)</source>
            <translation>عمق نویز پایین (متر)</translation>
        </message>
        <message>
            <source>Shortest facet edge (m)</source>
            <translation>کوتاه‌ترین ضلع وجه (متر)</translation>
        </message>
        <message>
            <source>Iteration cap</source>
            <translation>سقف تکرار</translation>
        </message>
        <message>
            <source>PTD: parcels {} m, distance {} m, angle {}°</source>
            <translation>PTD: قطعه‌ها {} متر، فاصله {} متر، زاویه {}°</translation>
        </message>
        <message>
            <source>Cliff-aware mirroring</source>
            <translation>قرینه‌سازی با درنظرگرفتن پرتگاه</translation>
        </message>
        <message>
            <source>Lowest point per cell for the step filter and the seeds.</source>
            <translation>پایین‌ترین نقطهٔ هر سلول برای فیلتر پله‌ای و بذرها.</translation>
        </message>
        <message>
            <source>Densification limit: distance of a point to its facet.</source>
            <translation>حد متراکم‌سازی: فاصلهٔ نقطه تا وجه مثلث.</translation>
        </message>
        <message>
            <source>Densification limit: angle under which a point is seen from the facet's vertices.</source>
            <translation>حد متراکم‌سازی: زاویه‌ای که نقطه از رأس‌های وجه دیده می‌شود.</translation>
        </message>
        <message>
            <source>Points this close to the final TIN are ground.</source>
            <translation>نقاطی که تا این اندازه به TIN نهایی نزدیک‌اند زمین‌اند.</translation>
        </message>
        <message>
            <source>Points deeper below the final TIN get class 7.</source>
            <translation>نقاط عمیق‌تر از این زیر TIN نهایی کلاس 7 می‌گیرند.</translation>
        </message>
        <message>
            <source>Points in a TIN facet that spans a cliff (steeper than 45° and higher than the distance to facet) are mirrored through nearby TIN vertices and accepted when the mirror lies on the cliff foot or top within the final distance, so the ground right at the cliff edge is kept.</source>
            <translation>نقاطی که در وجهی از TIN قرار دارند که از روی یک پرتگاه می‌گذرد (تندتر از 45° و بلندتر از فاصله تا وجه) نسبت به رأس‌های نزدیک TIN قرینه می‌شوند و اگر قرینه در فاصلهٔ نهایی روی پای پرتگاه یا بالای آن بیفتد پذیرفته می‌شوند، تا زمینِ درست لبهٔ پرتگاه حفظ شود.</translation>
        </message>
        <message>
            <source>&lt;p&gt;Reference: Axelsson, P. (2000). &lt;cite&gt;DEM generation from laser scanner data using adaptive TIN models&lt;/cite&gt;. IAPRS XXXIII-B4, 110–117.&lt;/p&gt;</source>
            <translation>&lt;p&gt;مرجع: &lt;bdi dir="ltr"&gt;Axelsson, P. (2000). &lt;cite&gt;DEM generation from laser scanner data using adaptive TIN models&lt;/cite&gt;. IAPRS XXXIII-B4, 110–117.&lt;/bdi&gt;&lt;/p&gt;</translation>
        </message>
        <message>
            <source>Larger than the largest building.</source>
            <translation>بزرگ‌تر از بزرگ‌ترین ساختمان.</translation>
        </message>
        <message>
            <source>A parcel's seed is its lowest point not more than the seed depth below this quantile of the parcel's lowest points per cell, so a cluster of low outliers never seeds the TIN.</source>
            <translation>بذر هر قطعه پایین‌ترین نقطهٔ آن است که بیش از عمق بذر زیر این چندکِ پایین‌ترین نقاط سلول‌های قطعه نباشد، تا خوشه‌ای از نقاط پرت پایین هرگز بذر TIN نشود.</translation>
        </message>
        <message>
            <source>See the seed quantile.</source>
            <translation>چندک بذر را ببینید.</translation>
        </message>
        <message>
            <source>The lowest point per cell of this size is a candidate of the TIN; every other point is classified by its distance to the final TIN (0 = every point).</source>
            <translation>پایین‌ترین نقطهٔ هر سلول به این اندازه نامزد TIN است؛ هر نقطهٔ دیگر با فاصله‌اش تا TIN نهایی طبقه‌بندی می‌شود (0 = همهٔ نقاط).</translation>
        </message>
        <message>
            <source>Seed quantile (%)</source>
            <translation>چندک بذر (%)</translation>
        </message>
        <message>
            <source>Seed depth (m)</source>
            <translation>عمق بذر (متر)</translation>
        </message>
        <message>
            <source>Candidate cell (m)</source>
            <translation>سلول نامزد (متر)</translation>
        </message>
        <message>
            <source>Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) and low noise (class 7) by progressive TIN densification (Axelsson 2000): the lowest trusted point of each parcel larger than the largest building seeds a TIN, which takes the candidates (the lowest point per candidate cell) close enough to its facets until none is added; every other point is ground when it lies close to the final TIN. Its mean total error on the 8 ISPRS samples is 4.55 % at the defaults (Axelsson published 4.82 % over all 15 samples): use the recommended ground filter unless you need a TIN filter.</source>
            <translation>ابر نقطهٔ LAS/LAZ را به زمین (کلاس 2)، نقاط دیگر (کلاس 1) و نویز پایین (کلاس 7) با متراکم‌سازی تدریجی TIN (Axelsson 2000) طبقه‌بندی می‌کند: پایین‌ترین نقطهٔ مطمئن هر قطعهٔ بزرگ‌تر از بزرگ‌ترین ساختمان بذر یک TIN می‌شود که نقاط نامزد (پایین‌ترین نقطهٔ هر سلول نامزد) را که به‌قدر کافی به وجه‌هایش نزدیک‌اند می‌پذیرد تا جایی که نقطه‌ای افزوده نشود؛ هر نقطهٔ دیگر اگر به TIN نهایی نزدیک باشد زمین است. میانگین خطای کل آن روی 8 نمونهٔ ISPRS با پیش‌فرض‌ها 4.55 % است (Axelsson روی هر 15 نمونه 4.82 % گزارش کرد): مگر به فیلتر TIN نیاز دارید، فیلتر زمین پیشنهادی را به کار ببرید.</translation>
        </message>
    </context>
    <context>
        <name>PublishOutputsAlgorithm</name>
        <message>
            <source>Publish chain outputs</source>
            <translation>انتشار خروجی‌های زنجیره</translation>
        </message>
        <message>
            <source>Classified point cloud to publish</source>
            <translation>ابر نقاط طبقه‌بندی‌شده برای انتشار</translation>
        </message>
        <message>
            <source>Ground filter report to publish</source>
            <translation>گزارش فیلتر زمین برای انتشار</translation>
        </message>
        <message>
            <source>DTM to publish</source>
            <translation>مدل رقومی زمین برای انتشار</translation>
        </message>
        <message>
            <source>DTM report to publish</source>
            <translation>گزارش مدل رقومی زمین برای انتشار</translation>
        </message>
        <message>
            <source>Check-point residuals to publish</source>
            <translation>باقی‌مانده‌های نقاط چک برای انتشار</translation>
        </message>
        <message>
            <source>DTM accuracy report to publish</source>
            <translation>گزارش دقت مدل رقومی زمین برای انتشار</translation>
        </message>
        <message>
            <source>Point cloud of the chain (never overwritten)</source>
            <translation>ابر نقاط زنجیره (هرگز بازنویسی نمی‌شود)</translation>
        </message>
        <message>
            <source>Check point file of the chain (never overwritten)</source>
            <translation>فایل نقاط چک زنجیره (هرگز بازنویسی نمی‌شود)</translation>
        </message>
        <message>
            <source>Check point layer of the chain (never overwritten)</source>
            <translation>لایهٔ نقاط چک زنجیره (هرگز بازنویسی نمی‌شود)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>گزارش فیلتر زمین</translation>
        </message>
        <message>
            <source>DTM</source>
            <translation>مدل رقومی زمین (DTM)</translation>
        </message>
        <message>
            <source>DTM report</source>
            <translation>گزارش مدل رقومی زمین</translation>
        </message>
        <message>
            <source>Check-point residuals</source>
            <translation>باقیمانده‌های نقاط چک</translation>
        </message>
        <message>
            <source>DTM accuracy report</source>
            <translation>گزارش دقت مدل رقومی زمین</translation>
        </message>
        <message>
            <source>Published {path}</source>
            <translation>منتشر شد: {path}</translation>
        </message>
        <message>
            <source>Copies the files written by the earlier steps of a model to their destinations, all of them or none: it is the last step of the model 'LiDAR to DTM with accuracy', so a destination that cannot be written leaves no classified cloud, DTM or report anywhere. Every destination is checked against the model's inputs, the files to publish and the other destinations first; one in another format than its file (.las for a .laz cloud) is converted.</source>
            <translation>فایل‌هایی را که گام‌های پیشین یک مدل نوشته‌اند به مقصدهایشان کپی می‌کند، همه یا هیچ‌کدام: این آخرین گام مدل «از LiDAR تا DTM همراه با دقت» است، پس مقصدی که نوشتن در آن ممکن نباشد هیچ ابر طبقه‌بندی‌شده، DTM یا گزارشی در هیچ جا باقی نمی‌گذارد. هر مقصد ابتدا با ورودی‌های مدل، فایل‌های انتشار و مقصدهای دیگر سنجیده می‌شود؛ مقصدی با قالبی جز قالب فایلش (.las برای ابر .laz) تبدیل می‌شود.</translation>
        </message>
        <message>
            <source>Unset: this file is not published.</source>
            <translation>اگر تعیین نشود: این فایل منتشر نمی‌شود.</translation>
        </message>
        <message>
            <source>Never overwritten: checked against every destination.</source>
            <translation>هرگز بازنویسی نمی‌شود: با هر مقصد سنجیده می‌شود.</translation>
        </message>
    </context>
    <context>
        <name>QObject</name>
        <message>
            <source>%1 [optional]</source>
            <translation>%1 [اختیاری]</translation>
        </message>
    </context>
    <context>
        <name>RectifyBatchAlgorithm</name>
        <message>
            <source>Rectify a folder of images with GCPs (batch)</source>
            <translation>تصحیح پوشه‌ای از تصاویر با نقاط کنترل (دسته‌ای)</translation>
        </message>
        <message>
            <source>Warps every image of a folder with its .points file and summarises the accuracy in one table.</source>
            <translation>هر تصویر پوشه را با فایل ‎.points‎ آن تصحیح و دقت را در یک جدول خلاصه می‌کند.</translation>
        </message>
        <message>
            <source>georeference,gcp,batch,folder,rectification,warp,rms</source>
            <translation>georeference,gcp,batch,folder,rectification,warp,rms,زمین‌مرجع,دسته‌ای,پوشه,تصحیح</translation>
        </message>
        <message>
            <source>Folder of images with .points files</source>
            <translation>پوشهٔ تصاویر با فایل‌های .points</translation>
        </message>
        <message>
            <source>Resampling</source>
            <translation>بازنمونه‌برداری</translation>
        </message>
        <message>
            <source>Folder of rectified images</source>
            <translation>پوشهٔ تصاویر تصحیح‌شده</translation>
        </message>
        <message>
            <source>Summary table</source>
            <translation>جدول خلاصه</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>پرونده‌های CSV (*.csv)</translation>
        </message>
        <message>
            <source>Rectifies every image of a folder that has its QGIS Georeferencer .points file next to it, with a fixed transformation or the one recommended for each image. It writes one summary table with the transformation, RMS_T, the check or leave-one-out error and the verdict of every image.</source>
            <translation>هر تصویرِ یک پوشه را که فایل ‎.points‎ زمین‌مرجع‌ساز QGIS کنارش است، با یک تبدیل ثابت یا تبدیل توصیه‌شده برای هر تصویر تصحیح می‌کند. یک جدول خلاصه با تبدیل، RMS_T، خطای چک یا حذف‌یکی و رأی نهایی هر تصویر می‌نویسد.</translation>
        </message>
        <message>
            <source>Each image with its .points file next to it (scan.tif + scan.tif.points).</source>
            <translation>هر تصویر با فایل ‎.points‎ کنارش (scan.tif + scan.tif.points).</translation>
        </message>
        <message>
            <source>The last choice picks the recommended transformation for each image.</source>
            <translation>گزینهٔ آخر تبدیل توصیه‌شده را برای هر تصویر برمی‌گزیند.</translation>
        </message>
        <message>
            <source>One rectified GeoTIFF per image, each written all or nothing.</source>
            <translation>یک GeoTIFF تصحیح‌شده برای هر تصویر که کامل نوشته می‌شود یا اصلاً نوشته نمی‌شود.</translation>
        </message>
        <message>
            <source>Batch rectification report</source>
            <translation>گزارش تصحیح دسته‌ای</translation>
        </message>
        <message>
            <source>Images found</source>
            <translation>تصاویر یافت‌شده</translation>
        </message>
        <message>
            <source>Images rectified</source>
            <translation>تصاویر تصحیح‌شده</translation>
        </message>
        <message>
            <source>{image}: {kind}, RMS_T {rms:.4f}, {basis} RMS_T {honest:.4f}, {verdict} → {output}</source>
            <translation>{image}: {kind}، RMS_T {rms:.4f}، RMS_T ({basis}) {honest:.4f}، {verdict} ← {output}</translation>
        </message>
    </context>
    <context>
        <name>RectifyGcpAlgorithm</name>
        <message>
            <source>georeference,georeferencer,gcp,ground control points,polynomial,rectification,warp,gdalwarp,rms,accuracy</source>
            <translation>زمین‌مرجع‌سازی,georeferencer,gcp,نقاط کنترل زمینی,چندجمله‌ای,تصحیح هندسی,warp,gdalwarp,rms,دقت</translation>
        </message>
        <message>
            <source>Target CRS [default: the GCP CRS]</source>
            <translation>سیستم مختصات مقصد [پیش‌فرض: سیستم مختصات نقاط کنترل]</translation>
        </message>
        <message>
            <source>Resampling</source>
            <translation>بازنمونه‌برداری</translation>
        </message>
        <message>
            <source>Output resolution (target CRS units) [default: GR]</source>
            <translation>قدرت تفکیک خروجی (به واحد سیستم مختصات مقصد) [پیش‌فرض: GR]</translation>
        </message>
        <message>
            <source>Output nodata value</source>
            <translation>مقدار nodata خروجی</translation>
        </message>
        <message>
            <source>Rectified image</source>
            <translation>تصویر تصحیح‌شده</translation>
        </message>
        <message>
            <source>OUTPUT must be a GeoTIFF file (.tif); got {0}.</source>
            <translation>OUTPUT باید پروندهٔ GeoTIFF (.tif) باشد؛ مقدار داده‌شده: {0}.</translation>
        </message>
        <message>
            <source>Rectify image with GCPs</source>
            <translation>تصحیح تصویر با نقاط کنترل زمینی</translation>
        </message>
        <message>
            <source>Rectifies (warps) an image with ground control points through GDAL: a polynomial of order 1–3, a linear, Helmert, projective or thin-plate-spline transformation, or the one with the lowest check-point error. It writes the accuracy report by the paper's criteria and never modifies the input image.</source>
            <translation>یک تصویر را با نقاط کنترل زمینی از راه GDAL تصحیح هندسی می‌کند: چندجمله‌ای درجهٔ 1–3، تبدیل خطی، هلمرت، تصویری یا اسپلاین صفحهٔ نازک، یا تبدیلی که کمترین خطای نقاط چک را دارد. گزارش دقت را بر پایهٔ معیارهای مقاله می‌نویسد و تصویر ورودی را هرگز تغییر نمی‌دهد.</translation>
        </message>
        <message>
            <source>GDAL reprojects after the transformation.</source>
            <translation>GDAL پس از تبدیل، تصویر را بازتصویر می‌کند.</translation>
        </message>
        <message>
            <source>Nearest neighbour, as in the paper.</source>
            <translation>نزدیک‌ترین همسایه، همانند مقاله.</translation>
        </message>
        <message>
            <source>Default: the input's nodata, else 0.</source>
            <translation>پیش‌فرض: مقدار بدون دادهٔ ورودی، وگرنه 0.</translation>
        </message>
        <message>
            <source>GCP rectification report</source>
            <translation>گزارش تصحیح با نقاط کنترل زمینی</translation>
        </message>
        <message>
            <source>Wrote {path}: {width} × {height} px at {resolution:.6g} {unit}/px, resampling {resampling}.</source>
            <translation>{path} نوشته شد: {width} × {height} پیکسل با {resolution:.6g} {unit}/پیکسل، بازنمونه‌گیری {resampling}.</translation>
        </message>
    </context>
    <context>
        <name>SlopeGroundFilterAlgorithm</name>
        <message>
            <source>Ground filter (slope-based)</source>
            <translation>فیلتر نقاط زمینی (مبتنی بر شیب)</translation>
        </message>
        <message>
            <source>lidar,las,laz,ground,filter,classification,dtm,bare earth,vosselman,slope,point cloud</source>
            <translation>لایدار,las,laz,زمین,فیلتر,طبقه‌بندی,dtm,زمین لخت,vosselman,شیب,ابر نقاط</translation>
        </message>
        <message>
            <source>Radius r (m)</source>
            <translation>شعاع r (متر)</translation>
        </message>
        <message>
            <source>Slope threshold θ (degrees)</source>
            <translation>آستانهٔ شیب θ (درجه)</translation>
        </message>
        <message>
            <source>Height tolerance h (m)</source>
            <translation>تلورانس ارتفاعی h (متر)</translation>
        </message>
        <message>
            <source>Keep existing noise classes (7, 18)</source>
            <translation>حفظ کلاس‌های نویز موجود (7, 18)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط زمینی</translation>
        </message>
        <message>
            <source>Points read</source>
            <translation>نقاط خوانده‌شده</translation>
        </message>
        <message>
            <source>Ground points (class 2)</source>
            <translation>نقاط زمینی (کلاس 2)</translation>
        </message>
        <message>
            <source>Non-ground points (class 1)</source>
            <translation>نقاط غیرزمینی (کلاس 1)</translation>
        </message>
        <message>
            <source>Low outliers (class 7)</source>
            <translation>نقاط پرت پایین (کلاس 7)</translation>
        </message>
        <message>
            <source>Filter speed (points/s)</source>
            <translation>سرعت فیلتر (نقطه/ثانیه)</translation>
        </message>
        <message>
            <source>Slope filter: r = {} m, θ = {}°, h = {} m, {} returns, mode {}</source>
            <translation>فیلتر شیب: ⁦r = {}⁩ متر، ⁦θ = {}°⁩، ⁦h = {}⁩ متر، بازگشت‌ها: {}، حالت: {}</translation>
        </message>
        <message>
            <source>Classifies a LAS/LAZ point cloud into ground (class 2) and non-ground (class 1) with Vosselman's (2000) slope-based filter: a point is non-ground when a neighbour within the radius r lies more than d·tan θ + h below it. The filter is exact and fast (about a million points per second at r = 3 m); tune r and θ to your data with the slope filter threshold sweep.</source>
            <translation>ابر نقاط LAS/LAZ را با فیلتر مبتنی بر شیب Vosselman ‏(2000) به زمین (کلاس 2) و غیرزمین (کلاس 1) کلاس‌بندی می‌کند: نقطه‌ای غیرزمینی است که همسایه‌ای درون شعاع r بیش از d·tan θ + h پایین‌تر از آن باشد. فیلتر دقیق و سریع است (حدود یک میلیون نقطه در ثانیه در r = 3 m)؛ r و θ را با ابزار پیمایش آستانه‌های فیلتر شیب برای دادهٔ خود تنظیم کنید.</translation>
        </message>
        <message>
            <source>Must exceed half the width of the largest building to remove; a larger radius costs more time.</source>
            <translation>باید از نصف عرض بزرگ‌ترین ساختمانی که باید حذف شود بیشتر باشد؛ شعاع بزرگ‌تر زمان بیشتری می‌برد.</translation>
        </message>
        <message>
            <source>The steepest terrain kept, between 0 and 90°; the allowed rise at 3 m is 2.52 m at 40°, 2.90 m at 44° and 3.84 m at 52°.</source>
            <translation>تندترین زمینی که حفظ می‌شود، بین 0 و 90°؛ افزایش ارتفاع مجاز در 3 m برابر 2.52 m در 40°، 2.90 m در 44° و 3.84 m در 52° است.</translation>
        </message>
        <message>
            <source>Extra rise allowed for every pair, absorbs ranging noise; 0 is the published rule.</source>
            <translation>افزایش ارتفاع اضافیِ مجاز برای هر جفت نقطه که نوفهٔ فاصله‌یابی را جذب می‌کند؛ 0 همان قاعدهٔ منتشرشده است.</translation>
        </message>
        <message>
            <source>Points already in class 7 or 18 keep their class and take no part.</source>
            <translation>نقاطی که از پیش در کلاس 7 یا 18 هستند کلاس خود را نگه می‌دارند و شرکت نمی‌کنند.</translation>
        </message>
        <message>
            <source>Every point with classes 2, 1 and 7; every other attribute is copied unchanged.</source>
            <translation>همهٔ نقاط با کلاس‌های 2، 1 و 7؛ همهٔ ویژگی‌های دیگر بدون تغییر رونوشت می‌شوند.</translation>
        </message>
        <message>
            <source>Slope ground filter report</source>
            <translation>گزارش فیلتر زمین مبتنی بر شیب</translation>
        </message>
    </context>
    <context>
        <name>SlopeThresholdSweepAlgorithm</name>
        <message>
            <source>Slope filter threshold sweep</source>
            <translation>پیمایش آستانه‌های فیلتر شیب</translation>
        </message>
        <message>
            <source>lidar,ground,filter,vosselman,slope,threshold,tuning,accuracy,type I,type II,kappa,isprs</source>
            <translation>لایدار,زمین,فیلتر,vosselman,شیب,آستانه,تنظیم,دقت,نوع اول,نوع دوم,کاپا,isprs</translation>
        </message>
        <message>
            <source>Reference cloud (empty = the input's classification)</source>
            <translation>ابر مرجع (خالی = طبقه‌بندی خود ورودی)</translation>
        </message>
        <message>
            <source>Reference ground classes</source>
            <translation>کلاس‌های زمینی مرجع</translation>
        </message>
        <message>
            <source>Slope thresholds θ (degrees; list or start:stop:step)</source>
            <translation>آستانه‌های شیب θ (درجه؛ فهرست یا شروع:پایان:گام)</translation>
        </message>
        <message>
            <source>Radii r (m; list)</source>
            <translation>شعاع‌های r (متر؛ فهرست)</translation>
        </message>
        <message>
            <source>Height tolerances h (m; list)</source>
            <translation>تلورانس‌های ارتفاعی h (متر؛ فهرست)</translation>
        </message>
        <message>
            <source>Best by</source>
            <translation>معیار انتخاب بهترین</translation>
        </message>
        <message>
            <source>Lowest total error</source>
            <translation>کمترین خطای کل</translation>
        </message>
        <message>
            <source>Highest kappa</source>
            <translation>بیشترین کاپا</translation>
        </message>
        <message>
            <source>Lowest Type I error</source>
            <translation>کمترین خطای نوع اول</translation>
        </message>
        <message>
            <source>Lowest Type II error</source>
            <translation>کمترین خطای نوع دوم</translation>
        </message>
        <message>
            <source>Sweep table</source>
            <translation>جدول پیمایش</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>پرونده‌های CSV (*.csv)</translation>
        </message>
        <message>
            <source>Classified with the best setting</source>
            <translation>طبقه‌بندی‌شده با بهترین تنظیم</translation>
        </message>
        <message>
            <source>Best radius (m)</source>
            <translation>بهترین شعاع (متر)</translation>
        </message>
        <message>
            <source>Best slope threshold (degrees)</source>
            <translation>بهترین آستانهٔ شیب (درجه)</translation>
        </message>
        <message>
            <source>Best height tolerance (m)</source>
            <translation>بهترین تلورانس ارتفاعی (متر)</translation>
        </message>
        <message>
            <source>Type I error at the best setting (%)</source>
            <translation>خطای نوع اول در بهترین تنظیم (%)</translation>
        </message>
        <message>
            <source>Type II error at the best setting (%)</source>
            <translation>خطای نوع دوم در بهترین تنظیم (%)</translation>
        </message>
        <message>
            <source>Total error at the best setting (%)</source>
            <translation>خطای کل در بهترین تنظیم (%)</translation>
        </message>
        <message>
            <source>Kappa at the best setting (%)</source>
            <translation>کاپا در بهترین تنظیم (%)</translation>
        </message>
        <message>
            <source>Settings evaluated</source>
            <translation>تعداد تنظیمات ارزیابی‌شده</translation>
        </message>
        <message>
            <source>Best setting</source>
            <translation>بهترین تنظیم</translation>
        </message>
        <message>
            <source>Sweeping {} thresholds × {} radii × {} tolerances</source>
            <translation>پیمایش {} آستانه × {} شعاع × {} تلورانس</translation>
        </message>
        <message>
            <source>Best ({}): {} — total {:.2f} %</source>
            <translation>بهترین ({}): {} — خطای کل {:.2f} %</translation>
        </message>
        <message>
            <source>Runs the slope-based ground filter for every combination of slope thresholds θ, radii r and height tolerances h, and measures each against reference labels: Type I and Type II errors, total error and Cohen's kappa (Sithole &amp;amp; Vosselman 2004). It then picks the best setting, at the cost of one neighbourhood pass per radius and tolerance.</source>
            <translation>فیلتر زمینِ مبتنی بر شیب را برای هر ترکیب از آستانه‌های شیب θ، شعاع‌های r و رواداری‌های ارتفاعی h اجرا می‌کند و هر یک را با برچسب‌های مرجع می‌سنجد: خطای نوع اول و دوم، خطای کل و ضریب کاپای کوهن (Sithole &amp;amp; Vosselman 2004). سپس بهترین تنظیم را برمی‌گزیند، با هزینهٔ یک گذر همسایگی برای هر شعاع و رواداری.</translation>
        </message>
        <message>
            <source>Its classification is never used to filter.</source>
            <translation>کلاس‌بندی آن هرگز در فیلتر به کار نمی‌رود.</translation>
        </message>
        <message>
            <source>A labelled copy of the same points in the same order, e.g. the ISPRS reference samples.</source>
            <translation>رونوشتی برچسب‌دار از همان نقاط با همان ترتیب، مانند نمونه‌های مرجع ISPRS.</translation>
        </message>
        <message>
            <source>Every other class counts as an object.</source>
            <translation>هر کلاس دیگر عارضه به شمار می‌آید.</translation>
        </message>
        <message>
            <source>A list such as 40, 44, 48 or start:stop:step.</source>
            <translation>فهرستی مانند 40, 44, 48 یا start:stop:step.</translation>
        </message>
        <message>
            <source>Each value is one neighbourhood pass.</source>
            <translation>هر مقدار یک گذر همسایگی است.</translation>
        </message>
        <message>
            <source>One row per setting with the cross matrix and the errors in percent.</source>
            <translation>یک سطر برای هر تنظیم با ماتریس متقاطع و خطاها به درصد.</translation>
        </message>
        <message>
            <source>Slope threshold sweep report</source>
            <translation>گزارش پیمایش آستانه‌های فیلتر شیب</translation>
        </message>
    </context>
    <context>
        <name>TinDtmAlgorithm</name>
        <message>
            <source>DTM by TIN (Delaunay linear interpolation)</source>
            <translation>مدل رقومی زمین با TIN (درون‌یابی خطی دلونی)</translation>
        </message>
        <message>
            <source>Terrain raster from the planes of the ground points' Delaunay triangles, gaps left empty.</source>
            <translation>رستر زمین از صفحه‌های مثلث‌های دلونی نقاط زمین، با شکاف‌های خالی.</translation>
        </message>
        <message>
            <source>dtm,dem,tin,delaunay,triangulation,linear,gdal_grid,blast2dem,lidar,ground,raster</source>
            <translation>مدل رقومی زمین,dem,tin,دلونی,مثلث‌بندی,خطی,gdal_grid,blast2dem,لایدار,زمین,رستر</translation>
        </message>
        <message>
            <source>Maximum triangle edge (m, 0 = auto)</source>
            <translation>بیشینهٔ طول ضلع مثلث (متر، 0 = خودکار)</translation>
        </message>
        <message>
            <source>Fill gaps (keep long triangles)</source>
            <translation>پر کردن شکاف‌ها (نگه داشتن مثلث‌های بلند)</translation>
        </message>
        <message>
            <source>TIN DTM</source>
            <translation>مدل رقومی زمین TIN</translation>
        </message>
        <message>
            <source>TIN DTM report</source>
            <translation>گزارش مدل رقومی زمین TIN</translation>
        </message>
        <message>
            <source>Triangulates the ground points of a LAS/LAZ file (Delaunay) and gives every cell centre the height of the plane of its triangle, as &lt;code&gt;gdal_grid -a linear&lt;/code&gt; does. Triangles with an edge longer than the maximum are dropped, so gaps under buildings or water stay nodata unless you fill them.</source>
            <translation>نقاط زمینی یک فایل LAS/LAZ را مثلث‌بندی (دلونی) می‌کند و به مرکز هر سلول ارتفاع صفحهٔ مثلث آن را می‌دهد، همان کاری که &lt;code&gt;gdal_grid -a linear&lt;/code&gt; می‌کند. مثلث‌هایی که ضلعی بلندتر از بیشینه دارند حذف می‌شوند، پس شکاف‌های زیر ساختمان‌ها یا آب بدون داده می‌مانند مگر آن‌ها را پر کنید.</translation>
        </message>
        <message>
            <source>0 = ten mean point spacings (at least four cells); cells in longer triangles are nodata.</source>
            <translation>0 = ده برابر میانگین فاصلهٔ نقاط (دست‌کم چهار سلول)؛ سلول‌های درون مثلث‌های بلندتر بدون داده می‌مانند.</translation>
        </message>
        <message>
            <source>Keeps every triangle, bridging gaps inside the convex hull with flat facets.</source>
            <translation>همهٔ مثلث‌ها را نگه می‌دارد و شکاف‌های درون پوش محدب را با وجه‌های تخت پر می‌کند.</translation>
        </message>
        <message>
            <source>Points triangulated</source>
            <translation>نقاط مثلث‌بندی‌شده</translation>
        </message>
        <message>
            <source>Triangles</source>
            <translation>مثلث‌ها</translation>
        </message>
        <message>
            <source>Cells with a value</source>
            <translation>سلول‌های دارای مقدار</translation>
        </message>
        <message>
            <source>Nodata cells</source>
            <translation>سلول‌های بدون داده</translation>
        </message>
    </context>
    <context>
        <name>TransformationParams</name>
        <message>
            <source>CRS of the GCP map coordinates (if the file does not say)</source>
            <translation>سیستم مختصاتِ مختصات نقشه‌ای نقاط کنترل (اگر پرونده آن را مشخص نکند)</translation>
        </message>
        <message>
            <source>Transformation</source>
            <translation>تبدیل</translation>
        </message>
        <message>
            <source>polynomial of the order set below</source>
            <translation>چندجمله‌ای با درجهٔ تعیین‌شده در پایین</translation>
        </message>
        <message>
            <source>polynomial order 1 (affine)</source>
            <translation>چندجمله‌ای درجهٔ 1 (آفین)</translation>
        </message>
        <message>
            <source>polynomial order 2</source>
            <translation>چندجمله‌ای درجهٔ 2</translation>
        </message>
        <message>
            <source>polynomial order 3</source>
            <translation>چندجمله‌ای درجهٔ 3</translation>
        </message>
        <message>
            <source>linear (shift and scale per axis)</source>
            <translation>خطی (انتقال و مقیاس برای هر محور)</translation>
        </message>
        <message>
            <source>Helmert (shift, scale, rotation)</source>
            <translation>هلمرت (انتقال، مقیاس، دوران)</translation>
        </message>
        <message>
            <source>projective (homography)</source>
            <translation>تصویری (هموگرافی)</translation>
        </message>
        <message>
            <source>thin-plate spline</source>
            <translation>اسپلاین صفحهٔ نازک</translation>
        </message>
        <message>
            <source>recommended (lowest check-point / leave-one-out error)</source>
            <translation>پیشنهادی (کمترین خطای نقاط چک / حذف‌یکی)</translation>
        </message>
        <message>
            <source>Polynomial order (1–3)</source>
            <translation>درجهٔ چندجمله‌ای (1–3)</translation>
        </message>
        <message>
            <source>Refine GCPs: drop the worst while over the tolerance</source>
            <translation>پالایش نقاط: حذف بدترین تا وقتی بالای تلورانس است</translation>
        </message>
    </context>
    <context>
        <name>_GcpBase</name>
        <message>
            <source>Image (raster) to rectify</source>
            <translation>تصویر (رستر) برای تصحیح</translation>
        </message>
        <message>
            <source>Image (raster) the GCPs were measured on</source>
            <translation>تصویر (رستر) که نقاط کنترل روی آن اندازه‌گیری شده‌اند</translation>
        </message>
        <message>
            <source>GCP file (.points or CSV)</source>
            <translation>پروندهٔ نقاط کنترل زمینی (.points یا CSV)</translation>
        </message>
        <message>
            <source>GCP files (*.points *.csv *.txt);;All files (*.*)</source>
            <translation>پرونده‌های نقاط کنترل (*.points *.csv *.txt);;همهٔ پرونده‌ها (*.*)</translation>
        </message>
        <message>
            <source>…or GCP point layer</source>
            <translation>…یا لایهٔ نقطه‌ای نقاط کنترل</translation>
        </message>
        <message>
            <source>Layer field: image column</source>
            <translation>فیلد لایه: ستون تصویر</translation>
        </message>
        <message>
            <source>Layer field: image row</source>
            <translation>فیلد لایه: سطر تصویر</translation>
        </message>
        <message>
            <source>Layer field: point id</source>
            <translation>فیلد لایه: شناسهٔ نقطه</translation>
        </message>
        <message>
            <source>Layer field: enabled (1/0)</source>
            <translation>فیلد لایه: فعال (1/0)</translation>
        </message>
        <message>
            <source>Layer field: role (gcp/check)</source>
            <translation>فیلد لایه: نقش (gcp/check)</translation>
        </message>
        <message>
            <source>Layer field: weight (&gt; 0)</source>
            <translation>فیلد لایه: وزن (&gt; 0)</translation>
        </message>
        <message>
            <source>Image coordinates refer to</source>
            <translation>مختصات تصویر مربوط است به</translation>
        </message>
        <message>
            <source>pixel corners: (0,0) = top-left corner of the image (GDAL/QGIS)</source>
            <translation>گوشه‌های پیکسل: (0,0) = گوشهٔ بالا-چپ تصویر (GDAL/QGIS)</translation>
        </message>
        <message>
            <source>pixel centres: integer = centre of a pixel (0-based indices)</source>
            <translation>مراکز پیکسل: عدد صحیح = مرکز یک پیکسل (اندیس‌ها از 0)</translation>
        </message>
        <message>
            <source>Ground resolution GR (map units/pixel) [default: from the GCPs]</source>
            <translation>قدرت تفکیک زمینی GR (واحد نقشه/پیکسل) [پیش‌فرض: از نقاط کنترل]</translation>
        </message>
        <message>
            <source>INPUT: no image given or it cannot be opened; give a raster file.</source>
            <translation>INPUT: تصویری داده نشده یا باز نمی‌شود؛ یک پروندهٔ رستری بدهید.</translation>
        </message>
        <message>
            <source>INPUT: {0} is not a local raster file; save the image to a file first.</source>
            <translation>INPUT: {0} پروندهٔ رستری محلی نیست؛ ابتدا تصویر را در یک پرونده ذخیره کنید.</translation>
        </message>
        <message>
            <source>Give either GCP_FILE or GCP_LAYER, not both.</source>
            <translation>یا GCP_FILE یا GCP_LAYER را بدهید، نه هر دو.</translation>
        </message>
        <message>
            <source>No GCPs: give a GCP file (GCP_FILE, .points or CSV) or a point layer (GCP_LAYER with COL_FIELD and ROW_FIELD); no &lt;image&gt;.points file was found next to the image either.</source>
            <translation>نقطهٔ کنترلی وجود ندارد: یک پروندهٔ نقاط کنترل (GCP_FILE، .points یا CSV) یا یک لایهٔ نقطه‌ای (GCP_LAYER با COL_FIELD و ROW_FIELD) بدهید؛ پروندهٔ &lt;image&gt;.points هم کنار تصویر یافت نشد.</translation>
        </message>
        <message>
            <source>GCP_LAYER needs COL_FIELD and ROW_FIELD: the fields holding the image column and row of each point.</source>
            <translation>GCP_LAYER به COL_FIELD و ROW_FIELD نیاز دارد: فیلدهایی که ستون و سطر تصویر هر نقطه را در خود دارند.</translation>
        </message>
        <message>
            <source>GCP layer feature {0} has no geometry.</source>
            <translation>عارضهٔ {0} در لایهٔ نقاط کنترل هندسه ندارد.</translation>
        </message>
        <message>
            <source>The GCP map coordinates have no CRS: the file has no '#CRS:' line and GCP_CRS is not set. Set GCP_CRS (e.g. EPSG:22780) and run again.</source>
            <translation>مختصات نقشه‌ای نقاط کنترل سیستم مختصات ندارند: پرونده خط '#CRS:' ندارد و GCP_CRS تنظیم نشده است. GCP_CRS را تنظیم کنید (مثلاً EPSG:22780) و دوباره اجرا کنید.</translation>
        </message>
        <message>
            <source>The GCP CRS is geographic (degrees): the accuracy criteria need map units of length. Set TARGET_CRS (or GCP_CRS) to a projected CRS, e.g. the UTM zone of the image.</source>
            <translation>سیستم مختصات نقاط کنترل جغرافیایی (درجه) است: معیارهای دقت به واحدهای طولی نقشه نیاز دارند. TARGET_CRS (یا GCP_CRS) را روی یک سیستم مختصات تصویرشده تنظیم کنید، مثلاً زون UTM تصویر.</translation>
        </message>
        <message>
            <source>Refinement tolerance (map units) [default: C5 limit 5·GR]</source>
            <translation>تلورانس پالایش (واحد نقشه) [پیش‌فرض: حد C5 یعنی 5·GR]</translation>
        </message>
        <message>
            <source>Minimum GCPs kept by the refinement [default: minimum + 2]</source>
            <translation>حداقل نقاط باقی‌مانده پس از فیلتر [پیش‌فرض: حداقل + 2]</translation>
        </message>
        <message>
            <source>A QGIS Georeferencer .points file or a CSV table with id, col, row, X, Y and optional enabled, role (gcp or check) and weight. Give the file or a point layer.</source>
            <translation>فایل ‎.points‎ زمین‌مرجع‌ساز QGIS یا جدول CSV با ستون‌های id، col، row، X، Y و به‌دلخواه enabled، role ‏(gcp یا check) و weight. فایل یا یک لایهٔ نقطه‌ای را بدهید.</translation>
        </message>
        <message>
            <source>Its geometry gives the map coordinates; the fields below give the image coordinates.</source>
            <translation>هندسهٔ آن مختصات نقشه را می‌دهد؛ فیلدهای زیر مختصات تصویر را می‌دهند.</translation>
        </message>
        <message>
            <source>Needed when the file does not state its CRS.</source>
            <translation>وقتی فایل سامانهٔ مختصات خود را نمی‌گوید لازم است.</translation>
        </message>
        <message>
            <source>The last choice picks the transformation with the lowest check-point or leave-one-out error.</source>
            <translation>گزینهٔ آخر تبدیلی را برمی‌گزیند که کمترین خطای نقاط چک یا حذف‌یکی را دارد.</translation>
        </message>
        <message>
            <source>Drops the worst point while a residual exceeds the tolerance, keeping at least the minimum number of GCPs.</source>
            <translation>تا وقتی باقیمانده‌ای از رواداری بیشتر است بدترین نقطه را حذف می‌کند و دست‌کم کمینهٔ نقاط کنترل را نگه می‌دارد.</translation>
        </message>
        <message>
            <source>Sets the map scale S = 20000·GR and the tolerance band 4·GR to 6·GR of the criteria (Tishreen Univ. J. Eng. Sci. 38(2), 2016).</source>
            <translation>مقیاس نقشه S = 20000·GR و بازهٔ رواداری 4·GR تا 6·GR معیارها را تعیین می‌کند (مجلهٔ علوم مهندسی دانشگاه تشرین 38(2)، 2016).</translation>
        </message>
        <message>
            <source>Transformation used</source>
            <translation>تبدیل به‌کاررفته</translation>
        </message>
        <message>
            <source>Recommended transformation</source>
            <translation>تبدیل پیشنهادی</translation>
        </message>
        <message>
            <source>A run that gives the polynomial order but no transformation (the command line of earlier versions) uses a polynomial of that order.</source>
            <translation>اجرایی که درجهٔ چندجمله‌ای را بدون تبدیل می‌دهد (خط فرمان نسخه‌های پیشین) از چندجمله‌ای همان درجه استفاده می‌کند.</translation>
        </message>
        <message>
            <source>{kind}: fit RMS_T = {fit:.4f} {unit}, {basis} RMS_T = {honest:.4f} {unit} (n = {n}); verdict: {verdict}.</source>
            <translation>{kind}: RMS_T برازش = {fit:.4f} {unit}، RMS_T ({basis}) = {honest:.4f} {unit} (⁦n = {n}⁩)؛ نتیجه: {verdict}.</translation>
        </message>
        <message>
            <source>Recommended transformation: {kind}, the fewest parameters among those within 10 % of the best {basis} RMS_T ({ranking} {unit}).</source>
            <translation>تبدیل پیشنهادی: {kind}، کم‌پارامترترین در میان تبدیل‌هایی که RMS_T آن‌ها ({basis}) در 10 % بهترین است ({ranking} {unit}).</translation>
        </message>
        <message>
            <source>No transformation has enough GCPs to be judged on independent residuals; add GCPs.</source>
            <translation>هیچ تبدیلی نقاط کنترل زمینی کافی برای داوری با باقیمانده‌های مستقل ندارد؛ نقاط کنترل زمینی بیفزایید.</translation>
        </message>
        <message>
            <source>Refinement dropped GCP {id} (residual {residual:.4f} {unit}; {left} left).</source>
            <translation>پالایش، نقطهٔ کنترل زمینی {id} را کنار گذاشت (باقیمانده {residual:.4f} {unit}؛ {left} مانده).</translation>
        </message>
    </context>
    <context>
        <name>_GridAlgorithm</name>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Cell size (m)</source>
            <translation>اندازهٔ سلول (متر)</translation>
        </message>
        <message>
            <source>Extent</source>
            <translation>محدوده</translation>
        </message>
        <message>
            <source>CRS (overrides the LAS file's CRS)</source>
            <translation>سیستم مختصات (بر سیستم مختصات پروندهٔ LAS مقدم است)</translation>
        </message>
        <message>
            <source>Maximum distance to data (m, 0 = auto)</source>
            <translation>بیشینهٔ فاصله تا داده (متر، 0 = خودکار)</translation>
        </message>
        <message>
            <source>Fill data gaps (interpolate far from data)</source>
            <translation>پر کردن شکاف‌های داده (درون‌یابی دور از داده)</translation>
        </message>
        <message>
            <source>Report</source>
            <translation>گزارش</translation>
        </message>
        <message>
            <source>The point cloud has no CRS record and no CRS was given; set the CRS parameter (e.g. EPSG:32632). No output was written.</source>
            <translation>ابر نقاط رکورد سیستم مختصات ندارد و سیستم مختصاتی هم داده نشده است؛ پارامتر CRS را تنظیم کنید (مثلاً EPSG:32632). هیچ خروجی‌ای نوشته نشد.</translation>
        </message>
        <message>
            <source>Reading points of class(es) {} from {}</source>
            <translation>در حال خواندن نقاط کلاس(های) {} از {}</translation>
        </message>
        <message>
            <source>{} of {} points selected</source>
            <translation>{} نقطه از {} نقطه انتخاب شد</translation>
        </message>
        <message>
            <source>Classes used (none = all)</source>
            <translation>کلاس‌های به‌کاررفته (بدون انتخاب = همه)</translation>
        </message>
        <message>
            <source>Default: the extent of the selected points, snapped outward to whole cells so that tiles line up.</source>
            <translation>پیش‌فرض: گسترهٔ نقاط انتخاب‌شده که رو به بیرون تا سلول‌های کامل گسترش می‌یابد تا کاشی‌ها بر هم منطبق شوند.</translation>
        </message>
        <message>
            <source>Needed when the LAS file has no CRS.</source>
            <translation>وقتی فایل LAS سامانهٔ مختصات مرجع ندارد لازم است.</translation>
        </message>
        <message>
            <source>0 = five mean point spacings (at least two cells); cells farther from any point are nodata.</source>
            <translation>0 = پنج برابر میانگین فاصلهٔ نقاط (دست‌کم دو سلول)؛ سلول‌هایی که از همهٔ نقاط دورترند بدون داده می‌مانند.</translation>
        </message>
        <message>
            <source>Interpolates every cell, ignoring the maximum distance.</source>
            <translation>همهٔ سلول‌ها را درون‌یابی می‌کند و بیشینهٔ فاصله را نادیده می‌گیرد.</translation>
        </message>
        <message>
            <source>GeoTIFF (float32, nodata −9999) in the cloud's CRS.</source>
            <translation>فایل GeoTIFF (float32، مقدار بدون داده ‎−9999‎) در سامانهٔ مختصات ابر نقاط.</translation>
        </message>
        <message>
            <source>all</source>
            <translation>همه</translation>
        </message>
    </context>
    <context>
        <name>_GroundCommon</name>
        <message>
            <source>lidar,las,laz,ground,filter,classification,dtm,bare earth,point cloud</source>
            <translation>لایدار,las,laz,زمین,فیلتر,طبقه‌بندی,مدل رقومی زمین,زمین برهنه,ابر نقاط</translation>
        </message>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Keep existing noise classes (7, 18)</source>
            <translation>حفظ کلاس‌های نویز موجود (7, 18)</translation>
        </message>
        <message>
            <source>Classified point cloud</source>
            <translation>ابر نقاط طبقه‌بندی‌شده</translation>
        </message>
        <message>
            <source>Ground points</source>
            <translation>نقاط زمینی</translation>
        </message>
        <message>
            <source>Points read</source>
            <translation>نقاط خوانده‌شده</translation>
        </message>
        <message>
            <source>Ground points (class 2)</source>
            <translation>نقاط زمینی (کلاس 2)</translation>
        </message>
        <message>
            <source>Non-ground points (class 1)</source>
            <translation>نقاط غیرزمینی (کلاس 1)</translation>
        </message>
        <message>
            <source>Low outliers (class 7)</source>
            <translation>نقاط پرت پایین (کلاس 7)</translation>
        </message>
        <message>
            <source>Filter speed (points/s)</source>
            <translation>سرعت فیلتر (نقطه/ثانیه)</translation>
        </message>
        <message>
            <source>Ground filter report</source>
            <translation>گزارش فیلتر زمین</translation>
        </message>
        <message>
            <source>A .las or .laz file in a projected CRS (metres).</source>
            <translation>فایل .las یا .laz در یک دستگاه مختصات تصویری (به متر).</translation>
        </message>
        <message>
            <source>Every point with class 2 ground, 1 other or 7 low noise; every other attribute, VLR and the CRS copied unchanged.</source>
            <translation>هر نقطه با کلاس 2 زمین، 1 دیگر یا 7 نویز پایین؛ همهٔ ویژگی‌های دیگر، VLRها و دستگاه مختصات بدون تغییر کپی می‌شوند.</translation>
        </message>
        <message>
            <source>Only the ground points.</source>
            <translation>فقط نقاط زمین.</translation>
        </message>
        <message>
            <source>Points already classified 7 or 18 keep their class and take no part.</source>
            <translation>نقاطی که از پیش 7 یا 18 طبقه‌بندی شده‌اند کلاس خود را نگه می‌دارند و شرکت نمی‌کنند.</translation>
        </message>
        <message>
            <source>Points far below their neighbours (multipath) get class 7 and take no part: one stray low point would reject every ground point around it.</source>
            <translation>نقاطی که بسیار پایین‌تر از همسایه‌هایشان‌اند (چندمسیری) کلاس 7 می‌گیرند و در فیلتر شرکت نمی‌کنند: یک نقطهٔ پایینِ سرگردان همهٔ نقاط زمینیِ اطرافش را رد می‌کرد.</translation>
        </message>
        <message>
            <source>Side of the cells searched for lower neighbours.</source>
            <translation>ضلع سلول‌هایی که برای همسایه‌های پایین‌تر جست‌وجو می‌شوند.</translation>
        </message>
        <message>
            <source>A point this far below the points around it is a low outlier.</source>
            <translation>نقطه‌ای که این اندازه پایین‌تر از نقاط اطرافش باشد، نقطهٔ پرت پایین است.</translation>
        </message>
    </context>
    <context>
        <name>_SlopeCommon</name>
        <message>
            <source>Point cloud (LAS/LAZ)</source>
            <translation>ابر نقاط (LAS/LAZ)</translation>
        </message>
        <message>
            <source>Returns filtered</source>
            <translation>بازگشت‌های فیلترشونده</translation>
        </message>
        <message>
            <source>All returns</source>
            <translation>همهٔ بازگشت‌ها</translation>
        </message>
        <message>
            <source>Last returns only</source>
            <translation>فقط بازگشت‌های آخر</translation>
        </message>
        <message>
            <source>Mode</source>
            <translation>حالت</translation>
        </message>
        <message>
            <source>Exact (Vosselman 2000)</source>
            <translation>دقیق (Vosselman 2000)</translation>
        </message>
        <message>
            <source>Terrain-adaptive (toolbox extension)</source>
            <translation>سازگار با ناهمواری زمین (افزودهٔ جعبه‌ابزار)</translation>
        </message>
        <message>
            <source>Adaptive mode: trend cell (m)</source>
            <translation>حالت سازگار: سلول روند (متر)</translation>
        </message>
        <message>
            <source>Adaptive mode: trend window, &gt; largest building (m)</source>
            <translation>حالت سازگار: پنجرهٔ روند، &gt; بزرگ‌ترین ساختمان (متر)</translation>
        </message>
        <message>
            <source>TREND_CELL and TREND_WINDOW must be &gt; 0 metres in adaptive mode (e.g. 10 and 60).</source>
            <translation>در حالت سازگار، TREND_CELL و TREND_WINDOW باید &gt; 0 متر باشند (مثلاً 10 و 60).</translation>
        </message>
        <message>
            <source>NOISE_RADIUS and NOISE_THRESHOLD must be &gt; 0 metres (e.g. 5 and 1), or switch the NOISE pre-filter off.</source>
            <translation>NOISE_RADIUS و NOISE_THRESHOLD باید &gt; 0 متر باشند (مثلاً 5 و 1)، یا پیش‌فیلتر NOISE را خاموش کنید.</translation>
        </message>
        <message>
            <source>All returns: every return is classified and is a neighbour (the forest study). Last returns only: first and intermediate returns get class 1; files without return numbers count every point as a last return.</source>
            <translation>همهٔ بازگشت‌ها: هر بازگشت کلاس‌بندی می‌شود و همسایه به شمار می‌آید (مطالعهٔ جنگل). فقط بازگشت‌های آخر: بازگشت‌های اول و میانی کلاس 1 می‌گیرند؛ در فایل‌های بدون شمارهٔ بازگشت، هر نقطه بازگشت آخر به شمار می‌آید.</translation>
        </message>
        <message>
            <source>Points far below their neighbours (multipath) get class 7 and take no part: one stray low point would reject every ground point around it.</source>
            <translation>نقاطی که بسیار پایین‌تر از همسایه‌هایشان‌اند (چندمسیری) کلاس 7 می‌گیرند و در فیلتر شرکت نمی‌کنند: یک نقطهٔ پایینِ سرگردان همهٔ نقاط زمینیِ اطرافش را رد می‌کرد.</translation>
        </message>
        <message>
            <source>Terrain-adaptive (this toolbox's extension) applies the rule to heights above a smooth low terrain trend, so natural slopes steeper than θ are kept (ISPRS samp11: total error 21.0 % → 16.4 %); use a lower θ, about 30–35°, in this mode.</source>
            <translation>حالت سازگار با زمین (افزودهٔ این جعبه‌ابزار) قاعده را روی ارتفاع‌های بالای یک روند هموار و پایینِ زمین اعمال می‌کند، پس شیب‌های طبیعیِ تندتر از θ حفظ می‌شوند (ISPRS samp11: خطای کل 21.0 % ← 16.4 %)؛ در این حالت θ کوچک‌تر، حدود 30–35°، به کار ببرید.</translation>
        </message>
    </context>
</TS>
